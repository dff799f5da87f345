#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

// A node of the hierarchical solver's tree: a leaf (one element), a surface node (several
// elements of one input patch, all in its plane) or a cluster (several patches). Every node but a
// leaf has two children; the leaves under a node are a contiguous range of the leaf order.
struct HierarchyNode {
  Eigen::Vector3f boundsMin, boundsMax;
  Eigen::Vector3f centroid;  // area-weighted: on the plane of a surface node
  Eigen::Vector3f normal;    // surface nodes and leaves: the patch's front normal; clusters: 0
  float area = 0;            // the leaves' areas (the problem's: exposed parts only)
  int child[2] = {-1, -1};
  int parent = -1;
  int leafBegin = 0, leafEnd = 0;  // its leaves, positions in the leaf order
  int patch = -1;                  // the input patch of a surface node or leaf; -1: a cluster

  bool isLeaf() const { return child[0] < 0; }
  bool isCluster() const { return patch < 0; }
  float radius() const { return 0.5f * (boundsMax - boundsMin).norm(); }
};

// The tree hierarchical radiosity links over (Hanrahan et al. 1991, with clustering after Smits
// et al. 1994 and Sillion 1995). Its leaves are the mesh's elements; above them, each input
// patch's elements are split in two at the median of their centroids along the longest axis,
// down to single elements (surface nodes), and above the patches, the patches are split the same
// way by their centroids (clusters), up to one root. Median splits keep the depth at about
// log2(elements), and the build costs O(n log n).
class NodeHierarchy {
 public:
  // `area`: each element's area as the solve counts it (the problem's exposed area).
  NodeHierarchy(const PatchMesh& mesh, const std::vector<double>& area);

  int size() const { return static_cast<int>(nodes_.size()); }
  int root() const { return 0; }
  const HierarchyNode& node(int n) const { return nodes_[n]; }
  // The element at a leaf-order position, and the leaf node of an element.
  int elementAt(int leafPosition) const { return elementOrder_[leafPosition]; }
  int element(int leafNode) const { return elementOrder_[nodes_[leafNode].leafBegin]; }
  int leafOf(int element) const { return leafNode_[element]; }
  int leafPosition(int element) const { return nodes_[leafNode_[element]].leafBegin; }
  // The root of each input patch's tree (the surface nodes right below the clusters), in leaf
  // order: the receivers' subtrees a Gauss–Seidel sweep visits one at a time.
  const std::vector<int>& patchRoots() const { return patchRoots_; }
  int clusterCount() const { return clusters_; }
  int depth() const { return depth_; }
  // The memory the tree holds, for the report.
  size_t bytes() const;

 private:
  int buildClusters(std::vector<int>& patches, int begin, int end, int depth);
  int buildSurface(std::vector<int>& elements, int begin, int end, int depth);
  int addNode();
  void finishInner(int n);

  const PatchMesh& mesh_;
  const std::vector<double>& area_;
  std::vector<HierarchyNode> nodes_;
  std::vector<int> elementOrder_, leafNode_, patchRoots_;
  std::vector<std::vector<int>> patchElements_;  // only while building
  std::vector<Eigen::Vector3d> centroids_;       // only while building: per element or patch
  int clusters_ = 0, depth_ = 0;
};

}  // namespace rad
