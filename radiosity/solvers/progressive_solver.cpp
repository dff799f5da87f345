#include "radiosity/solvers/progressive_solver.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/core/compensated_sum.h"

namespace rad {

ProgressiveSolver::ProgressiveSolver(const RadiosityProblem& problem, ShotRows& shots)
    : problem_(problem),
      shots_(shots),
      solution_(problem.emission),
      unshot_(shots.shooterCount()),
      shot_(shots.shooterCount()),
      received_(shots.shooterCount()),
      emittedPower_(problem.emittedPower()) {
  pointSolution_.resize(problem.size());
  for (int i = 0; i < problem.size(); ++i) pointSolution_[i].fill(problem.emission[i]);
  for (int i = 0; i < problem.size(); ++i)
    unshot_[shots_.shooterOf(i)] += problem.emission[i] * problem.area[i];
  updateUnshotTotals();
}

double ProgressiveSolver::powerKey(const Rgb& unshot) {
  // Magnitudes: after refinement a shooter may owe negative power (light to take back).
  return std::fabs(unshot.r) + std::fabs(unshot.g) + std::fabs(unshot.b);
}

void ProgressiveSolver::updateUnshotTotals() {
  // Every key from scratch (at the start and after refinement): O(n), rare.
  selection_.reset(unshot_.size());
  for (size_t s = 0; s < unshot_.size(); ++s) selection_.set(s, powerKey(unshot_[s]));
  refreshSelection();
}

void ProgressiveSolver::refreshSelection() {
  nextShooter_ = selection_.argmax();
  unshotFraction_ = emittedPower_ > 0 ? selection_.total() / emittedPower_ : 0.0;
}

void ProgressiveSolver::step() {
  if (nextShooter_ < 0) return;  // nothing left to shoot
  const int shooter = nextShooter_;
  const Rgb power = unshot_[shooter];
  unshot_[shooter] = Rgb();
  selection_.setLater(shooter, 0.0);
  shot_[shooter] += power / shots_.shooterArea(shooter);
  const FormFactorRow& row = shots_.powerFractions(shooter);
  for (size_t k = 0; k < row.targets.size(); ++k) {
    const int j = row.targets[k];
    // j receives power·fraction, reflects rho_j of it, spread over its area; what it reflects is
    // unshot power of j's shooter.
    const Rgb reflected = problem_.reflectance[j] * power * row.factor(k);
    solution_[j] += reflected / problem_.area[j];
    if (row.points.empty() || !row.tinted.empty()) {
      for (Rgb& b : pointSolution_[j]) b += reflected / problem_.area[j];
    } else {
      const Rgb perFraction = problem_.reflectance[j] * power / problem_.area[j];
      for (int p = 0; p < 3; ++p)
        pointSolution_[j][p] += perFraction * static_cast<double>(row.points[k][p]);
    }
    const int receiver = shots_.shooterOf(j);
    unshot_[receiver] += reflected;
    received_[receiver] += reflected;
    selection_.setLater(receiver, powerKey(unshot_[receiver]));
  }
  selection_.update();
  lastShooter_ = shooter;
  ++shotCount_;
  refreshSelection();
}

std::vector<Rgb> ProgressiveSolver::irradianceFrom(const std::vector<Rgb>& emission) {
  RAD_CHECK_EQ(emission.size(), solution_.size());
  std::vector<Rgb> power(shots_.shooterCount());
  for (int i = 0; i < problem_.size(); ++i)
    if (!emission[i].isZero()) power[shots_.shooterOf(i)] += emission[i] * problem_.area[i];
  std::vector<Rgb> irradiance(emission.size());
  for (int s = 0; s < static_cast<int>(power.size()); ++s) {
    if (power[s].isZero()) continue;
    const FormFactorRow& row = shots_.powerFractions(s);
    for (size_t k = 0; k < row.targets.size(); ++k) {
      const int j = row.targets[k];
      irradiance[j] += power[s] * row.factor(k) / problem_.area[j];
    }
  }
  return irradiance;
}

void ProgressiveSolver::startFrom(const std::vector<Rgb>& guess) {
  RAD_CHECK_EQ(guess.size(), solution_.size());
  RAD_CHECK_EQ(shots_.shooterCount(), problem_.size());  // element rows: shooter i is element i
  const int n = problem_.size();
  std::vector<Rgb> landed(n);  // power landing on each element from every shooter's B (W)
  for (int i = 0; i < n; ++i) {
    if (guess[i].isZero()) continue;
    const Rgb power = guess[i] * shots_.shooterArea(i);
    const FormFactorRow& row = shots_.powerFractions(i);
    for (size_t k = 0; k < row.targets.size(); ++k) landed[row.targets[k]] += power * row.factor(k);
  }
  // Each element has shot its guess B A, and holds what that landed on it: B' = E + ρ·landed / A.
  // What it holds and has not shot, (B' − B) A, is its unshot power.
  for (int j = 0; j < n; ++j) {
    const Rgb reflected = problem_.reflectance[j] * landed[j];
    solution_[j] = problem_.emission[j] + reflected / problem_.area[j];
    unshot_[j] = (solution_[j] - guess[j]) * problem_.area[j];
    shot_[j] = guess[j];
    received_[j] = reflected;
    pointSolution_[j].fill(solution_[j]);
  }
  updateUnshotTotals();
}

std::vector<Rgb> ProgressiveSolver::withAmbient() const {
  CompensatedSum areaSum;
  Rgb unshotSum, rhoSum;
  for (const Rgb& u : unshot_) unshotSum += u;
  for (int i = 0; i < problem_.size(); ++i) {
    areaSum += problem_.area[i];
    rhoSum += problem_.reflectance[i] * problem_.area[i];
  }
  const double totalArea = areaSum.value();
  std::vector<Rgb> out = solution_;
  if (!(totalArea > 0)) return out;
  Rgb ambient;
  for (int c = 0; c < 3; ++c) {
    const double meanRho = rhoSum[c] / totalArea;
    // Where every surface reflects all light (ρ = 1 is allowed) the series 1/(1 − ρ) has no sum:
    // the display estimate is capped instead of dividing by zero.
    ambient[c] = unshotSum[c] / totalArea / std::max(1.0 - meanRho, 1e-3);
  }
  for (int i = 0; i < problem_.size(); ++i) out[i] += problem_.reflectance[i] * ambient;
  return out;
}

void ProgressiveSolver::elementsChanged(
    const std::vector<int>& changed,
    const std::function<std::array<double, 3>(int, int)>& elementToShooter) {
  solution_.resize(problem_.size());
  pointSolution_.resize(problem_.size());
  std::vector<int> shotShooters;
  for (int s = 0; s < static_cast<int>(shot_.size()); ++s)
    if (shot_[s].maxComponent() > 0) shotShooters.push_back(s);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, changed.size(), 4), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k != r.end(); ++k) {
          const int e = changed[k];
          std::array<Rgb, 3> gathered;
          for (int s : shotShooters) {
            const std::array<double, 3> f = elementToShooter(e, s);
            for (int p = 0; p < 3; ++p)
              if (f[p] > 0) gathered[p] += f[p] * shot_[s];
          }
          for (int p = 0; p < 3; ++p)
            pointSolution_[e][p] = problem_.emission[e] + problem_.reflectance[e] * gathered[p];
          solution_[e] = (pointSolution_[e][0] + pointSolution_[e][1] + pointSolution_[e][2]) / 3.0;
        }
      });
  // Keep each shooter's books: its unshot power must match what its elements now reflect.
  std::vector<Rgb> reflectedNow(shot_.size());
  for (int e = 0; e < problem_.size(); ++e)
    reflectedNow[shots_.shooterOf(e)] += (solution_[e] - problem_.emission[e]) * problem_.area[e];
  for (size_t s = 0; s < shot_.size(); ++s) {
    unshot_[s] += reflectedNow[s] - received_[s];
    received_[s] = reflectedNow[s];
  }
  emittedPower_ = problem_.emittedPower();
  updateUnshotTotals();
}

std::vector<Rgb> ProgressiveSolver::unshotPowerOfElements() const {
  std::vector<Rgb> out(problem_.size());
  for (int i = 0; i < problem_.size(); ++i) {
    const int s = shots_.shooterOf(i);
    out[i] = unshot_[s] * (problem_.area[i] / shots_.shooterArea(s));
  }
  return out;
}

GatheringColumns::GatheringColumns(const RadiosityProblem& problem,
                                   const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows)
    : area_(problem.area), columns_(problem.size()) {
  // Row-major iteration visits (j, i) with j increasing, so each column comes out sorted by j.
  for (int j = 0; j < rows.outerSize(); ++j)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, j); it; ++it) {
      const int i = static_cast<int>(it.col());
      columns_[i].targets.push_back(j);
      columns_[i].values.push_back(it.value() * area_[j] / area_[i]);
    }
}

}  // namespace rad
