#include "radiosity/pipeline/kept_row_table.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <utility>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/huge_pages.h"

namespace rad {

KeptRowTable::KeptRowTable(const std::vector<FormFactorRow>& rows) {
  size_t factors = 0;
  for (const FormFactorRow& row : rows) {
    RAD_CHECK(row.tinted.empty() || row.tinted.size() == row.targets.size());
    factors += row.targets.size();
  }
  RAD_CHECK(factors <= static_cast<size_t>(std::numeric_limits<int>::max()));
  reserve(rows.size(), factors);
  int* outer = f_.outerIndexPtr();
  for (size_t i = 0; i < rows.size(); ++i)
    outer[i + 1] = outer[i] + static_cast<int>(rows[i].targets.size());
  f_.data().resize(static_cast<Eigen::Index>(factors));
  // The rows side by side: copying a large scene's 35 million factors (and faulting in their
  // fresh pages) took `update` a second and a half on one thread.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rows.size(), 256),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t i = range.begin(); i != range.end(); ++i) {
                        const FormFactorRow& row = rows[i];
                        const auto at = static_cast<size_t>(outer[i]);
                        for (size_t k = 0; k < row.targets.size(); ++k) {
                          f_.innerIndexPtr()[at + k] = row.targets[k];
                          // factors.bin keeps f32: the table holds what it will read back
                          f_.valuePtr()[at + k] = static_cast<float>(row.values[k]);
                        }
                      }
                    });
  for (const FormFactorRow& row : rows) {
    escaped_.push_back(row.escaped);
    if (!row.tinted.empty()) ++tintedRows_;
    tinted_.push_back(row.tinted);
  }
}

namespace {

// Row `v` of a kept table renumbered (entries mapped to -1 left out) into `out`, sorted by target,
// with `changes` merged in: a changed entry's factor is its count, changed, over the rays counted
// (as assemble writes it), an entry whose count falls to 0 is left out. Returns its escaped
// fraction.
double renumberedRow(const KeptRowTable::RowView& v, const std::vector<int>& newIndexOf,
                     const RowChanges* changes, std::vector<std::pair<int, double>>& out) {
  out.clear();
  bool sorted = true;
  for (size_t k = 0; k < v.count; ++k) {
    const int to = newIndexOf[static_cast<size_t>(v.targets[k])];
    if (to < 0) continue;
    sorted = sorted && (out.empty() || out.back().first < to);
    out.emplace_back(to, v.values[k]);
  }
  // The kept elements keep their order in the new mesh, so this is rare.
  if (!sorted) std::sort(out.begin(), out.end());
  if (!changes || changes->none()) return v.escaped;
  const int counted = changes->counted;
  RAD_CHECK(counted > 0);
  const double perRay = 1.0 / counted;
  auto changed = [&](double factor, int change) {
    const int64_t count = std::llround(factor * counted) + change;
    RAD_CHECK_GE(count, 0);  // updateRow refuses a change that takes a count below zero
    return static_cast<double>(count) * perRay;
  };
  // Merged in place from the back: the changes' new targets go in between.
  size_t k = out.size();
  size_t added = 0;
  for (const auto& [target, change] : changes->counts) {
    const auto at = std::lower_bound(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(k),
                                     std::make_pair(target, -1.0));
    added += at == out.begin() + static_cast<std::ptrdiff_t>(k) || at->first != target;
  }
  out.resize(k + added);
  size_t write = out.size();
  for (size_t c = changes->counts.size(); c-- > 0;) {
    const auto [target, change] = changes->counts[c];
    while (k > 0 && out[k - 1].first > target) out[--write] = out[--k];
    if (k > 0 && out[k - 1].first == target)
      out[--write] = {target, changed(out[--k].second, change)};
    else
      out[--write] = {target, changed(0.0, change)};
  }
  RAD_CHECK_EQ(write, k);  // the entries before the first change stay where they are
  out.erase(std::remove_if(out.begin(), out.end(), [](const auto& e) { return e.second == 0; }),
            out.end());
  return changed(v.escaped, static_cast<int>(changes->escaped));
}

}  // namespace

KeptRowTable::KeptRowTable(const std::vector<FormFactorRow>& rows, const KeptRowTable& kept,
                           const std::vector<int>& keptFrom, const std::vector<int>& newIndexOf,
                           const std::vector<RowChanges>& changes) {
  RAD_CHECK_EQ(rows.size(), keptFrom.size());
  RAD_CHECK(changes.empty() || changes.size() == rows.size());
  RAD_CHECK(!kept.anyTinted());
  const size_t n = rows.size();
  auto changesOf = [&](size_t i) { return changes.empty() ? nullptr : &changes[i]; };
  std::vector<size_t> count(n);
  std::vector<double> escaped(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256),
                    [&](const tbb::blocked_range<size_t>& r) {
                      std::vector<std::pair<int, double>> row;
                      for (size_t i = r.begin(); i != r.end(); ++i) {
                        if (keptFrom[i] < 0) {
                          count[i] = rows[i].targets.size();
                          escaped[i] = rows[i].escaped;
                          continue;
                        }
                        const RowView v = kept.view(static_cast<size_t>(keptFrom[i]));
                        const RowChanges* changed = changesOf(i);
                        if (changed && !changed->none()) {
                          escaped[i] = renumberedRow(v, newIndexOf, changed, row);
                          count[i] = row.size();
                          continue;
                        }
                        escaped[i] = v.escaped;  // unchanged: only the entries left out to count
                        size_t c = 0;
                        for (size_t k = 0; k < v.count; ++k)
                          c += newIndexOf[static_cast<size_t>(v.targets[k])] >= 0;
                        count[i] = c;
                      }
                    });
  size_t factors = 0;
  for (size_t c : count) factors += c;
  RAD_CHECK(factors <= static_cast<size_t>(std::numeric_limits<int>::max()));
  reserve(n, factors);
  int* outer = f_.outerIndexPtr();
  for (size_t i = 0; i < n; ++i) outer[i + 1] = outer[i] + static_cast<int>(count[i]);
  f_.data().resize(static_cast<Eigen::Index>(factors));
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, n, 256), [&](const tbb::blocked_range<size_t>& r) {
        std::vector<std::pair<int, double>> row;
        for (size_t i = r.begin(); i != r.end(); ++i) {
          int* targets = f_.innerIndexPtr() + outer[i];
          double* values = f_.valuePtr() + outer[i];
          if (keptFrom[i] < 0) {
            const FormFactorRow& fresh = rows[i];
            RAD_CHECK(fresh.tinted.empty());
            for (size_t k = 0; k < fresh.targets.size(); ++k) {
              targets[k] = fresh.targets[k];
              values[k] = static_cast<float>(fresh.values[k]);  // as factors.bin keeps them
            }
            continue;
          }
          renumberedRow(kept.view(static_cast<size_t>(keptFrom[i])), newIndexOf, changesOf(i), row);
          RAD_CHECK_EQ(row.size(), count[i]);
          for (size_t k = 0; k < row.size(); ++k) {
            targets[k] = row[k].first;
            values[k] = static_cast<float>(row[k].second);  // as factors.bin keeps them
          }
        }
      });
  escaped_ = std::move(escaped);
  tinted_.resize(n);
}

void KeptRowTable::reserve(size_t rows, size_t maxFactors) {
  RAD_CHECK(size() == 0);
  RAD_CHECK(rows < static_cast<size_t>(std::numeric_limits<int>::max()));
  // Eigen indexes the factors with int: beyond that no matrix holds them.
  if (maxFactors > static_cast<size_t>(std::numeric_limits<int>::max()))
    maxFactors = static_cast<size_t>(std::numeric_limits<int>::max());
  f_ = Matrix(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows));
  // Reserved, not written: untouched pages of the bound cost no memory.
  f_.data().reserve(static_cast<Eigen::Index>(maxFactors));
  adviseHugePages(f_.valuePtr(), maxFactors * sizeof(double));
  adviseHugePages(f_.innerIndexPtr(), maxFactors * sizeof(int));
  f_.outerIndexPtr()[0] = 0;
  escaped_.reserve(rows);
  tinted_.reserve(rows);
  reservedRows_ = rows;
}

void KeptRowTable::populateReserved() {
  const auto factors = static_cast<size_t>(f_.data().allocatedSize());
  populatePages(f_.valuePtr(), factors * sizeof(double));
  populatePages(f_.innerIndexPtr(), factors * sizeof(int));
}

void KeptRowTable::appendRow(const int32_t* targets, const float* values, size_t count,
                             double escaped, std::vector<Rgb> tinted) {
  RAD_CHECK(size() < reservedRows_);
  RAD_CHECK(tinted.empty() || tinted.size() == count);
  const auto at = static_cast<size_t>(f_.outerIndexPtr()[size()]);
  RAD_CHECK(count <= static_cast<size_t>(std::numeric_limits<int>::max()) - at);
  f_.data().resize(static_cast<Eigen::Index>(at + count));
  for (size_t k = 0; k < count; ++k) {
    f_.innerIndexPtr()[at + k] = targets[k];
    f_.valuePtr()[at + k] = values[k];
  }
  f_.outerIndexPtr()[size() + 1] = static_cast<int>(at + count);
  escaped_.push_back(escaped);
  if (!tinted.empty()) ++tintedRows_;
  tinted_.push_back(std::move(tinted));
}

void KeptRowTable::swap(KeptRowTable& other) noexcept {
  f_.swap(other.f_);
  escaped_.swap(other.escaped_);
  tinted_.swap(other.tinted_);
  std::swap(tintedRows_, other.tintedRows_);
  std::swap(reservedRows_, other.reservedRows_);
}

KeptRowTable::RowView KeptRowTable::view(size_t i) const {
  RAD_CHECK(i < size());
  RAD_CHECK_MSG(f_.rows() == static_cast<Eigen::Index>(size()), "the matrix is lent");
  const int begin = f_.outerIndexPtr()[i], end = f_.outerIndexPtr()[i + 1];
  return {f_.innerIndexPtr() + begin, f_.valuePtr() + begin, static_cast<size_t>(end - begin),
          escaped_[i], tinted_[i]};
}

FormFactorRow KeptRowTable::row(size_t i) const {
  const RowView v = view(i);
  FormFactorRow row;
  row.targets.assign(v.targets, v.targets + v.count);
  row.values.assign(v.values, v.values + v.count);
  row.tinted = v.tinted;
  row.escaped = v.escaped;
  return row;
}

KeptRowTable::Matrix KeptRowTable::takeMatrix() {
  Matrix f = lendMatrix();
  KeptRowTable().swap(*this);
  return f;
}

KeptRowTable::Matrix KeptRowTable::lendMatrix() {
  if (anyTinted())
    throw InputError(
        "form factors through mirrors or glass are tinted per channel; the gathering solvers "
        "use one matrix for all channels: use --solver progressive for this scene");
  RAD_CHECK(size() == reservedRows_);
  RAD_CHECK_MSG(f_.rows() == static_cast<Eigen::Index>(size()), "the matrix is already lent");
  Matrix f;
  f.swap(f_);  // Eigen 3.4's move copies every entry; swap does not
  return f;
}

void KeptRowTable::returnMatrix(Matrix&& f) {
  RAD_CHECK_MSG(f_.rows() == 0 && f.rows() == static_cast<Eigen::Index>(size()),
                "not the matrix this table lent");
  f_.swap(f);
}

}  // namespace rad
