#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/formfactors/form_factor_row.h"

namespace rad {

// The kept form-factor rows (factors.bin) held as the gathering solvers read them: one
// compressed-row matrix F, row i holding element i's factors to its targets in target order, with
// each row's escaped fraction and the per-channel factors of the rows that met mirrors or glass.
// One matrix, not a vector per row: relight reads 35 million factors of a large scene straight
// into it and hands it to Gauss–Seidel without a copy.
class KeptRowTable {
 public:
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  KeptRowTable() = default;
  explicit KeptRowTable(const std::vector<FormFactorRow>& rows);
  // An update's rows: rows[i] where keptFrom[i] < 0; otherwise row keptFrom[i] of `kept` (no row
  // of it tinted) with each target t renumbered to newIndexOf[t], the entries mapped to -1 left
  // out, and changes[i] (targets in the new numbering) merged in, copied straight from one table
  // to the other (no vector per row: for a large scene that was a second of fresh pages and
  // copies). `changes` is empty or holds one per row.
  KeptRowTable(const std::vector<FormFactorRow>& rows, const KeptRowTable& kept,
               const std::vector<int>& keptFrom, const std::vector<int>& newIndexOf,
               const std::vector<RowChanges>& changes = {});
  // Moves swap: Eigen 3.4's SparseMatrix "move" copies every entry (half a second for a large
  // scene's rows, each time a KeptFactors is returned or passed on).
  KeptRowTable(KeptRowTable&& other) noexcept { swap(other); }
  KeptRowTable& operator=(KeptRowTable&& other) noexcept {
    swap(other);
    return *this;
  }
  KeptRowTable(const KeptRowTable&) = default;
  KeptRowTable& operator=(const KeptRowTable&) = default;
  void swap(KeptRowTable& other) noexcept;

  size_t size() const { return escaped_.size(); }
  size_t factorCount() const { return static_cast<size_t>(f_.nonZeros()); }
  FormFactorRow row(size_t i) const;
  // Row i in place (valid while the table is unchanged), for a writer that copies it anyway.
  struct RowView {
    const int* targets;
    const double* values;
    size_t count;
    double escaped;
    const std::vector<Rgb>& tinted;
  };
  RowView view(size_t i) const;
  bool anyTinted() const { return tintedRows_ > 0; }

  // For a reader that knows the row count and a bound on the factors before the rows: appends
  // in row order. `tinted` is empty or holds one factor per target.
  void reserve(size_t rows, size_t maxFactors);
  // Faults in the reserved factor arrays (populatePages), from a thread beside the one appending.
  void populateReserved();
  void appendRow(const int32_t* targets, const float* values, size_t count, double escaped,
                 std::vector<Rgb> tinted);

  // F for the gathering solvers, moved out (the table is left empty). InputError when a row is
  // tinted: they use one matrix for all channels.
  Matrix takeMatrix();
  // F lent to a solver and given back when it is done (swapped both ways, no copy), so that the
  // table, still holding the rows, is then kept: `update` solves with the rows it writes. Rows
  // cannot be read meanwhile (RAD_CHECK). InputError as takeMatrix.
  Matrix lendMatrix();
  void returnMatrix(Matrix&& f);
  Matrix matrix() const { return KeptRowTable(*this).takeMatrix(); }  // a copy, the table kept

 private:
  Matrix f_;
  std::vector<double> escaped_;
  std::vector<std::vector<Rgb>> tinted_;  // per row: empty unless it met mirrors or glass
  size_t tintedRows_ = 0;
  size_t reservedRows_ = 0;
};

}  // namespace rad
