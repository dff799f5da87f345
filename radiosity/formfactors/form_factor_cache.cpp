#include "radiosity/formfactors/form_factor_cache.h"

#include <tbb/parallel_for.h>

#include <chrono>

#include "radiosity/core/errors.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/seconds_since.h"

namespace rad {
FormFactorCache::FormFactorCache(const HemisphereFormFactors& method)
    : method_(method), rows_(method.mesh().elementCount()) {}

const FormFactorRow& FormFactorCache::row(int element) {
  if (!rows_[element]) {
    const auto start = std::chrono::steady_clock::now();
    rows_[element] = std::make_unique<FormFactorRow>(method_.computeRow(element));
    ++rowsComputed_;
    raysCast_ += method_.raysForRow(element);
    seconds_ += secondsSince(start);
  }
  return *rows_[element];
}

void FormFactorCache::computeRows(const std::vector<bool>& needed, Progress* progress) {
  std::vector<int> todo;
  for (int i = 0; i < elementCount(); ++i)
    if (needed[i] && !rows_[i]) todo.push_back(i);
  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, todo.size(), 8), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t k = range.begin(); k != range.end(); ++k) {
          rows_[todo[k]] = std::make_unique<FormFactorRow>(method_.computeRow(todo[k]));
          if (progress) progress->advance(method_.raysForRow(todo[k]));
        }
      });
  rowsComputed_ += static_cast<int>(todo.size());
  for (int i : todo) raysCast_ += method_.raysForRow(i);
  seconds_ += secondsSince(start);
}

std::vector<FormFactorRow> FormFactorCache::takeAllRows(Progress* progress) {
  computeRows(std::vector<bool>(rows_.size(), true), progress);
  std::vector<FormFactorRow> rows;
  rows.reserve(rows_.size());
  for (auto& row : rows_) {
    rows.push_back(std::move(*row));
    *row = FormFactorRow();
  }
  return rows;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> FormFactorCache::matrix() const {
  for (const auto& row : rows_)
    if (row && !row->tinted.empty())
      throw InputError(
          "form factors through mirrors or glass are tinted per channel; the gathering solvers "
          "use one matrix for all channels: use --solver progressive for this scene");
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < elementCount(); ++i)
    if (rows_[i])
      for (size_t k = 0; k < rows_[i]->targets.size(); ++k)
        entries.emplace_back(i, rows_[i]->targets[k], rows_[i]->values[k]);
  Eigen::SparseMatrix<double, Eigen::RowMajor> f(elementCount(), elementCount());
  f.setFromTriplets(entries.begin(), entries.end());
  return f;
}

}  // namespace rad
