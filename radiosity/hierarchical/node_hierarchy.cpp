#include "radiosity/hierarchical/node_hierarchy.h"

#include <algorithm>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// The axis along which the points' bounding box is longest.
int longestAxis(const std::vector<Eigen::Vector3d>& point, const std::vector<int>& items, int begin,
                int end) {
  Eigen::Vector3d lo = point[items[begin]], hi = lo;
  for (int k = begin + 1; k < end; ++k) {
    lo = lo.cwiseMin(point[items[k]]);
    hi = hi.cwiseMax(point[items[k]]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

// Splits items[begin, end) in two halves at the median of their points along the longest axis
// (ties broken by index, so the tree does not depend on the standard library's partition).
int medianSplit(const std::vector<Eigen::Vector3d>& point, std::vector<int>& items, int begin,
                int end) {
  const int axis = longestAxis(point, items, begin, end);
  const int mid = begin + (end - begin) / 2;
  std::nth_element(
      items.begin() + begin, items.begin() + mid, items.begin() + end, [&](int a, int b) {
        return point[a][axis] < point[b][axis] || (point[a][axis] == point[b][axis] && a < b);
      });
  return mid;
}

}  // namespace

NodeHierarchy::NodeHierarchy(const PatchMesh& mesh, const std::vector<double>& area)
    : mesh_(mesh), area_(area) {
  const int elements = mesh.elementCount();
  RAD_CHECK(static_cast<int>(area.size()) == elements);
  RAD_CHECK(elements > 0);
  nodes_.reserve(2 * static_cast<size_t>(elements));
  elementOrder_.reserve(elements);
  leafNode_.assign(elements, -1);

  patchElements_.assign(mesh.patchCount(), {});
  for (int e = 0; e < elements; ++e) patchElements_[mesh.patch(e)].push_back(e);
  std::vector<int> patches;
  std::vector<Eigen::Vector3d> patchCentroid(mesh.patchCount(), Eigen::Vector3d::Zero());
  for (int p = 0; p < mesh.patchCount(); ++p) {
    if (patchElements_[p].empty()) continue;
    patches.push_back(p);
    double weight = 0;
    for (int e : patchElements_[p]) {
      patchCentroid[p] += mesh.area(e) * mesh.centroid(e);
      weight += mesh.area(e);
    }
    patchCentroid[p] = weight > 0 ? Eigen::Vector3d(patchCentroid[p] / weight)
                                  : mesh.centroid(patchElements_[p].front());
  }
  centroids_ = std::move(patchCentroid);
  buildClusters(patches, 0, static_cast<int>(patches.size()), 0);
  patchElements_ = {};
  centroids_ = {};
  RAD_CHECK(static_cast<int>(elementOrder_.size()) == elements);
}

int NodeHierarchy::addNode() {
  nodes_.emplace_back();
  return static_cast<int>(nodes_.size()) - 1;
}

// Bounds, area, centroid and leaf range of an inner node from its two children.
void NodeHierarchy::finishInner(int n) {
  HierarchyNode& node = nodes_[n];
  const HierarchyNode& a = nodes_[node.child[0]];
  const HierarchyNode& b = nodes_[node.child[1]];
  nodes_[node.child[0]].parent = n;
  nodes_[node.child[1]].parent = n;
  node.boundsMin = a.boundsMin.cwiseMin(b.boundsMin);
  node.boundsMax = a.boundsMax.cwiseMax(b.boundsMax);
  node.area = a.area + b.area;
  node.centroid = node.area > 0
                      ? Eigen::Vector3f((a.area * a.centroid + b.area * b.centroid) / node.area)
                      : Eigen::Vector3f(0.5f * (a.centroid + b.centroid));
  node.leafBegin = a.leafBegin;
  node.leafEnd = b.leafEnd;
  RAD_CHECK(a.leafEnd == b.leafBegin);
}

int NodeHierarchy::buildClusters(std::vector<int>& patches, int begin, int end, int depth) {
  RAD_CHECK(end > begin);
  if (end - begin == 1) {
    std::vector<int>& elements = patchElements_[patches[begin]];
    const int n = buildSurface(elements, 0, static_cast<int>(elements.size()), depth);
    patchRoots_.push_back(n);
    return n;
  }
  const int n = addNode();
  ++clusters_;
  depth_ = std::max(depth_, depth);
  const int mid = medianSplit(centroids_, patches, begin, end);
  const int left = buildClusters(patches, begin, mid, depth + 1);
  const int right = buildClusters(patches, mid, end, depth + 1);
  nodes_[n].child[0] = left;
  nodes_[n].child[1] = right;
  nodes_[n].normal.setZero();
  finishInner(n);
  return n;
}

int NodeHierarchy::buildSurface(std::vector<int>& elements, int begin, int end, int depth) {
  depth_ = std::max(depth_, depth);
  const int n = addNode();
  if (end - begin == 1) {
    const int e = elements[begin];
    HierarchyNode& leaf = nodes_[n];
    const auto c = mesh_.corners(e);
    leaf.boundsMin = c[0].cwiseMin(c[1]).cwiseMin(c[2]).cast<float>();
    leaf.boundsMax = c[0].cwiseMax(c[1]).cwiseMax(c[2]).cast<float>();
    leaf.centroid = mesh_.centroid(e).cast<float>();
    leaf.normal = mesh_.normal(e).cast<float>();
    leaf.area = static_cast<float>(area_[e]);
    leaf.patch = mesh_.patch(e);
    leaf.leafBegin = static_cast<int>(elementOrder_.size());
    leaf.leafEnd = leaf.leafBegin + 1;
    elementOrder_.push_back(e);
    leafNode_[e] = n;
    return n;
  }
  // The elements' centroids for this split only; the patch's list is reordered in place.
  std::vector<int> local(end - begin);
  std::vector<Eigen::Vector3d> centre(end - begin);
  for (int k = begin; k < end; ++k) {
    local[k - begin] = k - begin;
    centre[k - begin] = mesh_.centroid(elements[k]);
  }
  const int mid = begin + medianSplit(centre, local, 0, end - begin);
  std::vector<int> reordered(end - begin);
  for (int k = 0; k < end - begin; ++k) reordered[k] = elements[begin + local[k]];
  std::copy(reordered.begin(), reordered.end(), elements.begin() + begin);
  const int left = buildSurface(elements, begin, mid, depth + 1);
  const int right = buildSurface(elements, mid, end, depth + 1);
  HierarchyNode& node = nodes_[n];
  node.child[0] = left;
  node.child[1] = right;
  node.patch = nodes_[left].patch;
  const Eigen::Vector3f sum =
      nodes_[left].area * nodes_[left].normal + nodes_[right].area * nodes_[right].normal;
  node.normal = sum.norm() > 0 ? Eigen::Vector3f(sum.normalized()) : nodes_[left].normal;
  finishInner(n);
  return n;
}

size_t NodeHierarchy::bytes() const {
  return nodes_.capacity() * sizeof(HierarchyNode) +
         (elementOrder_.capacity() + leafNode_.capacity() + patchRoots_.capacity()) * sizeof(int);
}

}  // namespace rad
