#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/hierarchical/node_hierarchy.h"

namespace rad {

// The radiosity a cluster shows in a direction. A cluster's surfaces face every way, so its area
// average would give a receiver below a sunlit cornice the cornice's lit top as well as the dark
// underside it actually sees (measured on Sponza: 13% too much light overall). Instead each
// cluster keeps six bins, along ±x, ±y and ±z: bin k holds Σ A_i max(0, n_i·d_k) B_i over its
// surfaces, divided by Σ A_i max(0, n_i·d_k), the B of the surfaces facing d_k weighted by how
// squarely they face it. A link reads the bins towards its receiver blended by the squared
// components c_k² of the direction, each weighted by its bin's facing area too:
// Σ c_k² W_k B_k / Σ c_k² W_k, the projected-area average of what faces the receiver. So what
// faces away counts for nothing, and a bin no surface faces counts for nothing either (blending
// the bins' B alone read an empty bin as black: a generated room of boxes 1.5% dark).
class DirectionalClusters {
 public:
  explicit DirectionalClusters(const NodeHierarchy& tree);

  // Every cluster's bins from the B of the surface nodes right below the clusters (the patch
  // roots), deepest first.
  void pull(const std::vector<Rgb>& nodeB);
  // A patch root's B changed by `change`: its ancestors' bins follow at once (Gauss–Seidel).
  void addChange(int patchRoot, const Rgb& change);
  // The B `cluster` shows towards `direction` (unit length, from the cluster to the receiver).
  Rgb towards(int cluster, const Eigen::Vector3f& direction) const;
  size_t bytes() const {
    return slot_.capacity() * sizeof(int) + weight_.capacity() * sizeof(weight_[0]) +
           bins_.capacity() * sizeof(bins_[0]);
  }

 private:
  // How squarely a surface of normal n faces each bin's direction, times its area.
  static std::array<float, 6> facing(const HierarchyNode& surface);

  const NodeHierarchy& tree_;
  std::vector<int> slot_;                     // per node: its cluster's index, -1 for others
  std::vector<std::array<float, 6>> weight_;  // per cluster: Σ A max(0, n·d_k)
  std::vector<std::array<Rgb, 6>> bins_;      // per cluster: B facing d_k
};

}  // namespace rad
