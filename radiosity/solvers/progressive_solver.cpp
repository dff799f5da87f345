#include "radiosity/solvers/progressive_solver.h"

#include "radiosity/core/compensated_sum.h"

namespace rad {

ProgressiveSolver::ProgressiveSolver(const RadiosityProblem& problem, FormFactorCache& cache)
    : problem_(problem), cache_(&cache), solution_(problem.emission), unshot_(problem.size()),
      emittedPower_(problem.emittedPower()) {
  for (int i = 0; i < problem.size(); ++i) unshot_[i] = problem.emission[i] * problem.area[i];
  updateUnshotTotals();
}

ProgressiveSolver::ProgressiveSolver(const RadiosityProblem& problem,
                                     const Eigen::SparseMatrix<double, Eigen::RowMajor>& gatheringRows)
    : problem_(problem), columns_(gatheringRows), solution_(problem.emission),
      unshot_(problem.size()), emittedPower_(problem.emittedPower()) {
  for (int i = 0; i < problem.size(); ++i) unshot_[i] = problem.emission[i] * problem.area[i];
  updateUnshotTotals();
}

void ProgressiveSolver::updateUnshotTotals() {
  // One pass finds both the next shooter and the exact (compensated) unshot total, so the
  // convergence measure never drifts from what is really left.
  CompensatedSum total;
  double best = 0;
  nextShooter_ = -1;
  for (int i = 0; i < problem_.size(); ++i) {
    const double power = unshot_[i].sum();
    total += power;
    if (power > best) {
      best = power;
      nextShooter_ = i;
    }
  }
  unshotFraction_ = emittedPower_ > 0 ? total.value() / emittedPower_ : 0.0;
}

void ProgressiveSolver::step() {
  if (nextShooter_ < 0) return;  // nothing left to shoot
  const int shooter = nextShooter_;
  const Rgb power = unshot_[shooter];
  unshot_[shooter] = Rgb();
  // Power arriving at j is power·F_shooter,j (lazy) or, by reciprocity, power·A_j F_j,shooter /
  // A_shooter (columns); j reflects rho_j of it, spread over its area.
  auto receive = [&](int j, double fraction) {
    const Rgb reflected = problem_.reflectance[j] * (power * fraction);
    solution_[j] += reflected / problem_.area[j];
    unshot_[j] += reflected;
  };
  if (cache_) {
    const FormFactorRow& row = cache_->row(shooter);
    for (size_t k = 0; k < row.targets.size(); ++k) receive(row.targets[k], row.values[k]);
  } else {
    const double perArea = 1.0 / problem_.area[shooter];
    for (Eigen::SparseMatrix<double>::InnerIterator it(columns_, shooter); it; ++it)
      receive(static_cast<int>(it.row()), it.value() * problem_.area[it.row()] * perArea);
  }
  lastShooter_ = shooter;
  ++shots_;
  updateUnshotTotals();
}

std::vector<Rgb> ProgressiveSolver::withAmbient() const {
  CompensatedSum areaSum;
  Rgb unshotSum, rhoSum;
  for (int i = 0; i < problem_.size(); ++i) {
    areaSum += problem_.area[i];
    unshotSum += unshot_[i];
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

}  // namespace rad
