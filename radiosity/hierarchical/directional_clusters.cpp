#include "radiosity/hierarchical/directional_clusters.h"

#include <algorithm>

namespace rad {

std::array<float, 6> DirectionalClusters::facing(const HierarchyNode& surface) {
  std::array<float, 6> w{};
  for (int axis = 0; axis < 3; ++axis) {
    w[2 * axis] = surface.area * std::max(0.0f, surface.normal[axis]);
    w[2 * axis + 1] = surface.area * std::max(0.0f, -surface.normal[axis]);
  }
  return w;
}

DirectionalClusters::DirectionalClusters(const NodeHierarchy& tree) : tree_(tree) {
  slot_.assign(tree.size(), -1);
  int clusters = 0;
  for (int n = 0; n < tree.size(); ++n)
    if (tree.node(n).isCluster()) slot_[n] = clusters++;
  weight_.assign(clusters, {});
  bins_.assign(clusters, {});
  for (int n = tree.size() - 1; n >= 0; --n) {  // children after their parents
    if (slot_[n] < 0) continue;
    std::array<float, 6>& w = weight_[slot_[n]];
    for (int child : tree.node(n).child) {
      const std::array<float, 6> add =
          slot_[child] >= 0 ? weight_[slot_[child]] : facing(tree.node(child));
      for (int k = 0; k < 6; ++k) w[k] += add[k];
    }
  }
}

void DirectionalClusters::pull(const std::vector<Rgb>& nodeB) {
  for (int n = tree_.size() - 1; n >= 0; --n) {
    if (slot_[n] < 0) continue;
    std::array<Rgb, 6> sum{};
    for (int child : tree_.node(n).child) {
      if (slot_[child] >= 0) {
        for (int k = 0; k < 6; ++k)
          sum[k] += bins_[slot_[child]][k] * static_cast<double>(weight_[slot_[child]][k]);
      } else {
        const std::array<float, 6> w = facing(tree_.node(child));
        for (int k = 0; k < 6; ++k) sum[k] += nodeB[child] * static_cast<double>(w[k]);
      }
    }
    for (int k = 0; k < 6; ++k)
      bins_[slot_[n]][k] = weight_[slot_[n]][k] > 0 ? sum[k] / weight_[slot_[n]][k] : Rgb();
  }
}

void DirectionalClusters::addChange(int patchRoot, const Rgb& change) {
  const std::array<float, 6> w = facing(tree_.node(patchRoot));
  for (int a = tree_.node(patchRoot).parent; a >= 0; a = tree_.node(a).parent)
    for (int k = 0; k < 6; ++k)
      if (weight_[slot_[a]][k] > 0)
        bins_[slot_[a]][k] += change * static_cast<double>(w[k] / weight_[slot_[a]][k]);
}

Rgb DirectionalClusters::towards(int cluster, const Eigen::Vector3f& direction) const {
  const std::array<Rgb, 6>& bins = bins_[slot_[cluster]];
  const std::array<float, 6>& weight = weight_[slot_[cluster]];
  Rgb power;
  double shown = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float c = direction[axis];
    const int k = 2 * axis + (c < 0 ? 1 : 0);
    const double w = static_cast<double>(c * c) * weight[k];
    power += bins[k] * w;
    shown += w;
  }
  if (shown > 0) return power / shown;
  // Nothing in the cluster faces the receiver's way: its rays that hit it saw its surfaces
  // edge-on; their average is the best guess.
  for (int k = 0; k < 6; ++k) {
    power += bins[k] * static_cast<double>(weight[k]);
    shown += weight[k];
  }
  return shown > 0 ? power / shown : Rgb();
}

}  // namespace rad
