#pragma once

#include <Eigen/SparseCore>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// Progressive refinement (Cohen, Chen, Wallace, Greenberg 1988): each step shoots the unshot
// power of the element holding the most. The ambient term estimates the light not yet shot,
// for display.
//
// Two sources for the shot, which differ only through Monte Carlo noise:
// - lazy (the default): the shooter's own hemisphere row F_ij, computed only when it first
//   shoots; power U_i·F_ij reaches j. Black elements never gain unshot power, so they never
//   shoot and their rows are never computed. Because the estimated F is not exactly reciprocal,
//   this converges to the solution of B_j = E_j + rho_j sum_i (A_i F_ij / A_j) B_i, which equals
//   the gathering solution only up to the form factors' noise.
// - columns (Southwell iteration): given every gathering row up front, the shot from i uses the
//   column F_ji, so it converges to exactly the system Jacobi and Gauss–Seidel solve.
class ProgressiveSolver : public Solver {
 public:
  ProgressiveSolver(const RadiosityProblem& problem, FormFactorCache& cache);
  ProgressiveSolver(const RadiosityProblem& problem, const Eigen::SparseMatrix<double, Eigen::RowMajor>& gatheringRows);
  std::string name() const override { return cache_ ? "progressive" : "southwell"; }
  void step() override;
  double progress() const override { return unshotFraction_; }
  const std::vector<Rgb>& solution() const override { return solution_; }
  int iterations() const override { return shots_; }
  std::string progressMeasure() const override { return "unshot power / emitted power"; }

  // B_i + rho_i · ambient, with ambient = R · (area-weighted mean unshot radiosity) and
  // R = 1 / (1 − area-weighted mean rho), per channel: an image that is roughly right from the
  // first shot on. Not part of solution(), which holds only light actually transported.
  std::vector<Rgb> withAmbient() const;
  const std::vector<Rgb>& unshotPower() const { return unshot_; }  // W per channel
  int lastShooter() const { return lastShooter_; }

 private:
  void updateUnshotTotals();
  const RadiosityProblem& problem_;
  FormFactorCache* cache_ = nullptr;
  Eigen::SparseMatrix<double, Eigen::ColMajor> columns_;
  std::vector<Rgb> solution_;
  std::vector<Rgb> unshot_;
  int shots_ = 0;
  int lastShooter_ = -1;
  int nextShooter_ = -1;
  double unshotFraction_ = 0;
  double emittedPower_;
};

}  // namespace rad
