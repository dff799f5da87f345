#include <gtest/gtest.h>

#include "meshing/element_locator.h"

namespace rad {
namespace {

// Two patches: a unit square at z = 0 and one at z = 1, split into small elements.
PatchMesh makeTwoSquares() {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0}, {{4, 5, 6, 7}, 0}});
  mesh.subdivideUniform(0.02);
  return mesh;
}

Eigen::Vector3d pointAt(const PatchMesh& mesh, int element, const Eigen::Vector3d& w) {
  const auto c = mesh.corners(element);
  return w[0] * c[0] + w[1] * c[1] + w[2] * c[2];
}

TEST(ElementLocator, FindsTheElementHoldingEachCentroid) {
  const PatchMesh mesh = makeTwoSquares();
  const ElementLocator locator(mesh);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    Eigen::Vector3d w;
    ASSERT_EQ(locator.locate(mesh.patch(e), mesh.centroid(e), w), e);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], 1.0 / 3, 1e-12);
  }
}

TEST(ElementLocator, WeightsReproduceThePoint) {
  const PatchMesh mesh = makeTwoSquares();
  const ElementLocator locator(mesh);
  const Eigen::Vector3d p(0.3141, 0.2718, 1);
  Eigen::Vector3d w;
  const int e = locator.locate(1, p, w);
  ASSERT_GE(e, 0);
  EXPECT_EQ(mesh.patch(e), 1);
  EXPECT_GE(w.minCoeff(), 0);
  EXPECT_NEAR(w.sum(), 1, 1e-12);
  EXPECT_LT((pointAt(mesh, e, w) - p).norm(), 1e-12);
}

TEST(ElementLocator, PointJustOutsideThePatchTakesTheNearestElement) {
  const PatchMesh mesh = makeTwoSquares();
  const ElementLocator locator(mesh);
  // Just past the square's edge y = 0: the element on that edge under x = 0.5 is least outside.
  const Eigen::Vector3d p(0.5, -1e-9, 0);
  Eigen::Vector3d w;
  const int e = locator.locate(0, p, w);
  ASSERT_GE(e, 0);
  EXPECT_LT(w.minCoeff(), 0);
  EXPECT_GT(w.minCoeff(), -1e-6);
  EXPECT_LT((pointAt(mesh, e, w) - p).norm(), 1e-12);
}

}  // namespace
}  // namespace rad
