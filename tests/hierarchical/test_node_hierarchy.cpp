// The tree of hierarchical radiosity: every element one leaf, leaf ranges nested, areas summed,
// surface nodes within one patch, clusters above them.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/hierarchical/node_hierarchy.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

std::vector<double> areasOf(const PatchMesh& mesh) {
  std::vector<double> area(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) area[e] = mesh.area(e);
  return area;
}

TEST(NodeHierarchy, LeavesAreTheElementsAndRangesNest) {
  const PatchMesh mesh = testing::closedCube(0.01);
  const std::vector<double> area = areasOf(mesh);
  const NodeHierarchy tree(mesh, area);
  const int n = mesh.elementCount();
  ASSERT_EQ(tree.size(), 2 * n - 1);  // a binary tree over n leaves
  EXPECT_EQ(tree.clusterCount(), 6 - 1);
  EXPECT_EQ(static_cast<int>(tree.patchRoots().size()), 6);
  std::vector<int> seen(n, 0);
  for (int pos = 0; pos < n; ++pos) {
    const int e = tree.elementAt(pos);
    ++seen[e];
    EXPECT_EQ(tree.leafPosition(e), pos);
    EXPECT_TRUE(tree.node(tree.leafOf(e)).isLeaf());
    EXPECT_EQ(tree.element(tree.leafOf(e)), e);
  }
  for (int e = 0; e < n; ++e) EXPECT_EQ(seen[e], 1);
  const HierarchyNode& root = tree.node(tree.root());
  EXPECT_EQ(root.leafBegin, 0);
  EXPECT_EQ(root.leafEnd, n);
  EXPECT_NEAR(root.area, 6.0, 1e-5);
  for (int k = 0; k < tree.size(); ++k) {
    const HierarchyNode& node = tree.node(k);
    if (node.isLeaf()) continue;
    const HierarchyNode& a = tree.node(node.child[0]);
    const HierarchyNode& b = tree.node(node.child[1]);
    EXPECT_EQ(a.parent, k);
    EXPECT_EQ(b.parent, k);
    EXPECT_EQ(a.leafBegin, node.leafBegin);
    EXPECT_EQ(a.leafEnd, b.leafBegin);
    EXPECT_EQ(b.leafEnd, node.leafEnd);
    EXPECT_NEAR(node.area, a.area + b.area, 1e-6 * node.area);
    EXPECT_TRUE((node.boundsMin.array() <= a.boundsMin.array()).all());
    EXPECT_TRUE((node.boundsMax.array() >= b.boundsMax.array()).all());
    if (!node.isCluster()) {
      // A surface node holds one patch only, and so do its children.
      EXPECT_EQ(a.patch, node.patch);
      EXPECT_EQ(b.patch, node.patch);
      EXPECT_NEAR(node.normal.norm(), 1.0f, 1e-5f);
    }
  }
}

TEST(NodeHierarchy, MedianSplitsKeepTheDepthLogarithmic) {
  const PatchMesh mesh = testing::closedCube(0.0005);
  const NodeHierarchy tree(mesh, areasOf(mesh));
  const double log2n = std::log2(static_cast<double>(mesh.elementCount()));
  EXPECT_LE(tree.depth(), std::ceil(log2n) + 2) << mesh.elementCount() << " elements";
}

}  // namespace
}  // namespace rad
