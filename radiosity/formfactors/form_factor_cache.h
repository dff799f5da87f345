#pragma once

#include <Eigen/SparseCore>
#include <atomic>
#include <memory>
#include <vector>

#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/formfactors/shot_rows.h"

namespace rad {

class Progress;

// Rows of the form-factor matrix, computed on first use and kept. Progressive shooting asks for
// the rows of the elements it shoots from, one at a time; the gathering solvers ask for all the
// rows they need at once (in parallel). Either way each row is computed at most once.
class FormFactorCache : public ShotRows {
 public:
  explicit FormFactorCache(const HemisphereFormFactors& method);

  // Not thread-safe: called from the solver's thread.
  const FormFactorRow& row(int element);
  bool hasRow(int element) const { return rows_[element] != nullptr; }

  // Computes every row with needed[i] true that is not cached yet, in parallel.
  void computeRows(const std::vector<bool>& needed, Progress* progress = nullptr);

  // Every row, computed where missing, moved out (the cache keeps empty rows and its counts):
  // for a caller that keeps them after the solve, without a second copy in memory.
  std::vector<FormFactorRow> takeAllRows(Progress* progress = nullptr);

  // Takes `row` as element's row, computed elsewhere (kept from an earlier solve, still valid):
  // not counted as computed.
  void adopt(int element, FormFactorRow&& row) {
    rows_[element] = std::make_unique<FormFactorRow>(std::move(row));
  }

  // Sparse F with the cached rows (rows never computed are empty).
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix() const;

  int elementCount() const { return static_cast<int>(rows_.size()); }

  // Shooting from elements through their own rows: the power element i emits reaches j in the
  // fraction F_ij of i's hemisphere row.
  int shooterCount() const override { return elementCount(); }
  int shooterOf(int element) const override { return element; }
  double shooterArea(int shooter) const override { return method_.shootingArea(shooter); }
  const FormFactorRow& powerFractions(int shooter) override { return row(shooter); }
  std::string description() const override { return "element rows (hemisphere)"; }
  int rowsComputed() const { return rowsComputed_; }
  uint64_t raysCast() const { return raysCast_; }
  double seconds() const { return seconds_; }  // wall time spent computing rows

 private:
  const HemisphereFormFactors& method_;
  std::vector<std::unique_ptr<FormFactorRow>> rows_;
  int rowsComputed_ = 0;
  uint64_t raysCast_ = 0;
  double seconds_ = 0;
};

}  // namespace rad
