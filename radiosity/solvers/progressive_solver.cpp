#include "radiosity/solvers/progressive_solver.h"

#include "radiosity/core/compensated_sum.h"

namespace rad {

ProgressiveSolver::ProgressiveSolver(const RadiosityProblem& problem, ShotRows& shots)
    : problem_(problem), shots_(shots), solution_(problem.emission), unshot_(shots.shooterCount()),
      emittedPower_(problem.emittedPower()) {
  for (int i = 0; i < problem.size(); ++i)
    unshot_[shots_.shooterOf(i)] += problem.emission[i] * problem.area[i];
  updateUnshotTotals();
}

void ProgressiveSolver::updateUnshotTotals() {
  // One pass finds both the next shooter and the exact (compensated) unshot total, so the
  // convergence measure never drifts from what is really left.
  CompensatedSum total;
  double best = 0;
  nextShooter_ = -1;
  for (int s = 0; s < static_cast<int>(unshot_.size()); ++s) {
    const double power = unshot_[s].sum();
    total += power;
    if (power > best) {
      best = power;
      nextShooter_ = s;
    }
  }
  unshotFraction_ = emittedPower_ > 0 ? total.value() / emittedPower_ : 0.0;
}

void ProgressiveSolver::step() {
  if (nextShooter_ < 0) return;  // nothing left to shoot
  const int shooter = nextShooter_;
  const Rgb power = unshot_[shooter];
  unshot_[shooter] = Rgb();
  const FormFactorRow& row = shots_.powerFractions(shooter);
  for (size_t k = 0; k < row.targets.size(); ++k) {
    const int j = row.targets[k];
    // j receives power·fraction, reflects rho_j of it, spread over its area; what it reflects is
    // unshot power of j's shooter.
    const Rgb reflected = problem_.reflectance[j] * power * row.factor(k);
    solution_[j] += reflected / problem_.area[j];
    unshot_[shots_.shooterOf(j)] += reflected;
  }
  lastShooter_ = shooter;
  ++shotCount_;
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
    ambient[c] = unshotSum[c] / totalArea / (1.0 - meanRho);
  }
  for (int i = 0; i < problem_.size(); ++i) out[i] += problem_.reflectance[i] * ambient;
  return out;
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
