#pragma once

#include <algorithm>
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
    nodes_.assign(2 * leaves_, Node{});
    pending_.clear();
    for (size_t i = 0; i < n; ++i) nodes_[leaves_ + i].index = static_cast<int>(i);
    for (size_t node = leaves_ - 1; node >= 1; --node) pull(node);
  }

  size_t size() const { return n_; }
  double key(size_t i) const { return nodes_[leaves_ + i].key; }

  void set(size_t i, double key) {
    Node& leaf = nodes_[leaves_ + i];
    leaf.key = key;
    leaf.sum = key;
    for (size_t node = (leaves_ + i) / 2; node >= 1; node /= 2) pull(node);
  }

  // A batch of changes: setLater() changes keys without touching the tree, update() then
  // recomputes each ancestor of the changed leaves once, level by level. Cheaper than set() per key
  // when a shot changes hundreds of keys: the paths share their upper nodes, and the pulls of one
  // level do not wait on each other.
  void setLater(size_t i, double key) {
    Node& leaf = nodes_[leaves_ + i];
    leaf.key = key;
    leaf.sum = key;
    pending_.push_back(leaves_ + i);
  }
  void update() {
    std::sort(pending_.begin(), pending_.end());
    pending_.erase(std::unique(pending_.begin(), pending_.end()), pending_.end());
    // Parents of a sorted level come out sorted, duplicates side by side.
    while (!pending_.empty() && pending_.front() > 1) {
      size_t out = 0;
      for (size_t node : pending_) {
        const size_t parent = node / 2;
        if (out == 0 || pending_[out - 1] != parent) pending_[out++] = parent;
      }
      pending_.resize(out);
      for (size_t node : pending_) pull(node);
    }
    pending_.clear();
  }

  // Index of the largest key (lowest index among equals); -1 when every key is 0 (or n is 0).
  int argmax() const {
    const Node& root = nodes_[1];
    return (root.index >= 0 && root.key > 0) ? root.index : -1;
  }
  double total() const { return n_ == 0 ? 0.0 : nodes_[1].sum; }

 private:
  // Each node keeps its winner's key beside its index, so updating a path reads only the two
  // children (adjacent in memory), never the leaves.
  struct Node {
    double key = 0;  // the largest key below (leaf: its key)
    double sum = 0;  // the sum of the keys below
    int index = -1;  // where the largest key is; -1 below padding only
  };
  void pull(size_t node) {
    const Node& l = nodes_[2 * node];
    const Node& r = nodes_[2 * node + 1];
    Node& p = nodes_[node];
    // The left child holds the lower indices: it wins ties.
    const bool right = r.index >= 0 && (l.index < 0 || r.key > l.key);
    p.key = right ? r.key : l.key;
    p.index = right ? r.index : l.index;
    p.sum = l.sum + r.sum;
  }

  size_t n_ = 0, leaves_ = 1;
  std::vector<Node>
      nodes_;  // implicit binary tree: root 1, children 2k and 2k+1, leaves from leaves_
  std::vector<size_t> pending_;  // changed by setLater(), not yet updated
};

}  // namespace rad
