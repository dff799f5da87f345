#pragma once

#include <cstddef>
#include <vector>

namespace rad {

// Shooter selection for progressive shooting in O(log n): a tournament tree over n non-negative
// keys (each shooter's unshot power) that gives, after each change of one key, the index of the
// largest key and the sum of all keys.
//
// Ties go to the lowest index, exactly as a linear scan with `key > best` picks them, so shooting
// with the tree shoots the same shooters in the same order as scanning them all. The sum is a
// pairwise (tree-shaped) sum of non-negative terms: relative error below log2(n) ulp, and the
// same for any order of updates, so it stays deterministic.
class MaxPowerTree {
 public:
  explicit MaxPowerTree(size_t n = 0) { reset(n); }

  // n keys, all 0.
  void reset(size_t n) {
    n_ = n;
    leaves_ = 1;
    while (leaves_ < n) leaves_ *= 2;
    best_.assign(2 * leaves_, kNone);
    sum_.assign(2 * leaves_, 0.0);
    key_.assign(leaves_, 0.0);
    for (size_t i = 0; i < n; ++i) best_[leaves_ + i] = static_cast<int>(i);
    for (size_t node = leaves_ - 1; node >= 1; --node) pull(node);
  }

  size_t size() const { return n_; }
  double key(size_t i) const { return key_[i]; }

  void set(size_t i, double key) {
    key_[i] = key;
    sum_[leaves_ + i] = key;
    for (size_t node = (leaves_ + i) / 2; node >= 1; node /= 2) pull(node);
  }

  // Index of the largest key (lowest index among equals); -1 when every key is 0 (or n is 0).
  int argmax() const {
    const int i = best_[1];
    return (i != kNone && key_[i] > 0) ? i : -1;
  }
  double total() const { return n_ == 0 ? 0.0 : sum_[1]; }

 private:
  static constexpr int kNone = -1;
  void pull(size_t node) {
    const int l = best_[2 * node], r = best_[2 * node + 1];
    // The left child holds the lower indices: it wins ties.
    best_[node] = (r != kNone && (l == kNone || key_[r] > key_[l])) ? r : l;
    sum_[node] = sum_[2 * node] + sum_[2 * node + 1];
  }

  size_t n_ = 0, leaves_ = 1;
  std::vector<int> best_;     // per node: index of the largest key below it
  std::vector<double> sum_;   // per node: sum of the keys below it
  std::vector<double> key_;   // per leaf
};

}  // namespace rad
