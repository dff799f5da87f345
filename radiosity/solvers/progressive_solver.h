#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <functional>

#include "radiosity/formfactors/shot_rows.h"
#include "radiosity/solvers/max_power_tree.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/solvers/refinable_solver.h"

namespace rad {

// Progressive refinement (Cohen, Chen, Wallace, Greenberg 1988): each step shoots the unshot
// power of the shooter holding the most. Shooters and where their power lands come from a
// ShotRows: elements through their own hemisphere rows (computed on first shot; black elements
// never gain unshot power, so they never shoot and their rows are never computed), patches through
// analytic element-to-patch form factors (substructuring: patches shoot, elements receive), or
// the columns of the full gathering matrix (Southwell iteration: the very system Jacobi and
// Gauss–Seidel solve). With hemisphere rows, the estimated F is not exactly reciprocal, so
// shooting converges to B_j = E_j + rho_j sum_i (A_i F_ij / A_j) B_i: the gathering solution up
// to the form factors' noise. The ambient term estimates the light not yet shot, for display.
class ProgressiveSolver : public RefinableSolver {
 public:
  ProgressiveSolver(const RadiosityProblem& problem, ShotRows& shots);
  std::string name() const override { return name_; }
  void step() override;
  double progress() const override { return unshotFraction_; }
  const std::vector<Rgb>& solution() const override { return solution_; }
  // B at each element's 3 receiver points (in the order of the rows' `points`), whose mean is
  // solution(): where the rows resolve their receivers, a linear field over each element; where
  // they do not, the element's value three times.
  const std::vector<std::array<Rgb, 3>>& pointSolution() const override { return pointSolution_; }
  int iterations() const override { return shotCount_; }
  std::string progressMeasure() const override { return "unshot power / emitted power"; }
  // Each shooter's power Σ A E over its elements, spread by its row (computed if not yet shot).
  std::vector<Rgb> irradianceFrom(const std::vector<Rgb>& emission) override;
  // Continues from `guess` (B per element; `update` after an edit, from the solution before it)
  // instead of from the emission alone: every element has shot its guess B A, and holds what
  // that lands on it, B' = E + ρ Σ_i B_i A_i F_ij / A_j; what it holds and has not shot,
  // (B' − B) A, is its unshot power (negative where the guess is too bright). Shooting it
  // converges to the same solution as from the start, so a guess that is already that solution
  // leaves almost nothing to shoot. Reads every row: shooters must be the elements (RAD_CHECK).
  void startFrom(const std::vector<Rgb>& guess);

  // B_i + rho_i · ambient, with ambient = R · (area-weighted mean unshot radiosity) and
  // R = 1 / (1 − area-weighted mean rho), per channel: an image that is roughly right from the
  // first shot on. Not part of solution(), which holds only light actually transported.
  std::vector<Rgb> withAmbient() const;
  // Unshot power per element (W): each shooter's share, spread over its elements by area.
  std::vector<Rgb> unshotPowerOfElements() const;
  int lastShooter() const { return lastShooter_; }

  // Continues after the receiving elements were refined (shooters unchanged): the problem now
  // has more elements (the caller updated it), and each changed or new element gathers what all
  // shots so far sent it, B_e = E_e + rho_e sum_s F_es S_s with S_s the radiosity shooter s has
  // shot in total: exactly what it would hold had it existed from the start. Unshot power stays
  // with the shooters, so shooting goes on where it was.
  // elementToShooter gives the form factor at each of the element's 3 receiver points.
  void elementsChanged(const std::vector<int>& changed,
                       const std::function<std::array<double, 3>(int element, int shooter)>&
                           elementToShooter) override;
  void setName(std::string name) { name_ = std::move(name); }

 private:
  // Rebuilds the selection from every shooter's unshot power (start, refinement).
  void updateUnshotTotals();
  // Next shooter and unshot fraction from the selection tree, after keys changed.
  void refreshSelection();
  static double powerKey(const Rgb& unshot);
  const RadiosityProblem& problem_;
  ShotRows& shots_;
  std::string name_ = "progressive";
  std::vector<Rgb> solution_;
  std::vector<std::array<Rgb, 3>> pointSolution_;
  std::vector<Rgb> unshot_;    // per shooter, W
  std::vector<Rgb> shot_;      // per shooter: radiosity shot so far, W/m²
  std::vector<Rgb> received_;  // per shooter: reflected power its elements received so far, W
  // Largest unshot power and the total in O(log shooters) per change, instead of a scan of all
  // shooters per shot (which made shooting O(n²)); same shooter order as the scan.
  MaxPowerTree selection_;
  int shotCount_ = 0;
  int lastShooter_ = -1;
  int nextShooter_ = -1;
  double unshotFraction_ = 0;
  double emittedPower_;
};

// Southwell iteration as shooting: shooters are elements, and the power of i reaches j in the
// fraction A_j F_ji / A_i read from column i of the gathering matrix (all rows computed first).
class GatheringColumns : public ShotRows {
 public:
  GatheringColumns(const RadiosityProblem& problem,
                   const Eigen::SparseMatrix<double, Eigen::RowMajor>& rows);
  int shooterCount() const override { return static_cast<int>(area_.size()); }
  int shooterOf(int element) const override { return element; }
  double shooterArea(int shooter) const override { return area_[shooter]; }
  const FormFactorRow& powerFractions(int shooter) override { return columns_[shooter]; }
  std::string description() const override { return "columns of the gathering matrix"; }

 private:
  std::vector<double> area_;
  std::vector<FormFactorRow> columns_;
};

}  // namespace rad
