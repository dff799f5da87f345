// The refinement criterion on its own: what is displayed (vertex interpolation) against the
// solved element values, ranked by area × error², spent up to a per-pass target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "meshing/adaptive_refinement.h"

namespace rad {
namespace {

// The unit square at z = 0 split into elements of at most `area`.
PatchMesh unitSquare(double area) {
  PatchMesh mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{{0, 1, 2, 3}, 0}});
  mesh.subdivideUniform(area);
  return mesh;
}

template <class Field>
std::vector<double> sampled(const PatchMesh& mesh, Field field) {
  std::vector<double> values(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) values[e] = field(mesh.centroid(e));
  return values;
}

TEST(AdaptiveRefinement, AGentleLinearGradientIsNotRefined) {
  // Linear interpolation shows a linear field exactly (up to the one-sided vertex means at the
  // border, a few per cent of the 10% change across the square here), so nothing is worth a split.
  const PatchMesh mesh = unitSquare(1.0 / 64);
  const auto values =
      sampled(mesh, [](const Eigen::Vector3d& c) { return 1.0 + 0.1 * c.x() + 0.05 * c.y(); });
  EXPECT_TRUE(selectForRefinement(mesh, values, {}, {0.1, 0, 0}).empty());
}

TEST(AdaptiveRefinement, OneSidedMeansAtABorderAreSeenOnASteepGradient) {
  // L = 1 + 10 x: inside, the corner means sit on the plane; at the borders x = 0 and x = 1 each
  // corner's mean is taken on one side only and misses the recovered (exact) value by about
  // 10 · h / 3. The estimate must see that, and stay near zero inside.
  const PatchMesh mesh = unitSquare(1.0 / 256);
  const double h = std::sqrt(2.0 / 256);
  const auto values = sampled(mesh, [](const Eigen::Vector3d& c) { return 1.0 + 10.0 * c.x(); });
  const std::vector<double> error = displayedVariation(mesh, values);
  double border = 0, inside = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Eigen::Vector3d c = mesh.centroid(e);
    const double distance = std::min({c.x(), 1 - c.x(), c.y(), 1 - c.y()});
    if (distance > 1.5 * h) inside = std::max(inside, error[e]);
    if (c.x() < 0.5 * h || c.x() > 1 - 0.5 * h) border = std::max(border, error[e]);
  }
  EXPECT_GT(border, 10.0 * h / 10);
  EXPECT_LT(inside, 1e-9);
}

TEST(AdaptiveRefinement, AStepIsRefinedAlongItsLineOnly) {
  const PatchMesh mesh = unitSquare(1.0 / 64);
  const double h = std::sqrt(2.0 / 64);  // longest edge of an element
  const auto values =
      sampled(mesh, [](const Eigen::Vector3d& c) { return c.x() < 0.37 ? 1.0 : 0.1; });
  const std::vector<int> selected = selectForRefinement(mesh, values, {}, {0.1, 0, 0});
  ASSERT_FALSE(selected.empty());
  for (int e : selected)
    EXPECT_LT(std::fabs(mesh.centroid(e).x() - 0.37), 1.5 * h) << "element " << e;
}

TEST(AdaptiveRefinement, LargerErrorsComeFirst) {
  // Two steps on the same elements, one 20 times the height of the other: how much of each
  // element's mean the display misses depends on where the step crosses it, but the first half of
  // the high step's elements must all be ranked before any element of the low step.
  const PatchMesh mesh = unitSquare(1.0 / 64);
  const auto values = sampled(mesh, [](const Eigen::Vector3d& c) {
    return 1.0 + (c.x() < 0.3 ? 20.0 : 0.0) + (c.x() < 0.7 ? 1.0 : 0.0);
  });
  const std::vector<int> selected = selectForRefinement(mesh, values, {}, {0.05, 0, 0});
  int high = 0;
  for (int e : selected) high += mesh.centroid(e).x() < 0.5;
  ASSERT_GT(high, 0);
  ASSERT_LT(high, static_cast<int>(selected.size()));
  for (int k = 0; k < high / 2; ++k) EXPECT_LT(mesh.centroid(selected[k]).x(), 0.5) << "rank " << k;
}

TEST(AdaptiveRefinement, ShadowEdgeElementsAreCandidatesEvenWhenTheirMeanLooksRight) {
  const PatchMesh mesh = unitSquare(1.0 / 16);
  const std::vector<double> values(mesh.elementCount(), 1.0);  // constant: no visible error
  std::vector<char> shadow(mesh.elementCount(), 0);
  EXPECT_TRUE(selectForRefinement(mesh, values, shadow, {0.1, 0, 0}).empty());
  // Element 3 a little darker (1%, well under the 10% threshold): not a candidate on its own,
  // but one when a shadow edge crosses it.
  std::vector<double> perturbed = values;
  perturbed[3] = 0.99;
  auto selected = selectForRefinement(mesh, perturbed, shadow, {0.1, 0, 0});
  EXPECT_EQ(std::find(selected.begin(), selected.end(), 3), selected.end());
  shadow[3] = 1;
  selected = selectForRefinement(mesh, perturbed, shadow, {0.1, 0, 0});
  EXPECT_NE(std::find(selected.begin(), selected.end(), 3), selected.end());
}

TEST(AdaptiveRefinement, RefinementStopsAtTheTargetAndKeepsTheArea) {
  PatchMesh mesh = unitSquare(1.0 / 16);
  const auto values =
      sampled(mesh, [](const Eigen::Vector3d& c) { return c.x() < 0.37 ? 1.0 : 0.1; });
  const auto selected = selectForRefinement(mesh, values, {}, {0.1, 0, 0});
  const int before = mesh.elementCount();
  ASSERT_GT(selected.size(), 4u);
  const auto changed = refineElements(mesh, selected, {0.1, 0, 0}, before + 4);
  EXPECT_GE(mesh.elementCount(), before + 4);
  EXPECT_LE(mesh.elementCount(), before + 4 + 8);  // one bisection's propagation path at most
  EXPECT_NEAR(mesh.totalArea(), 1.0, 1e-12);
  EXPECT_GE(changed.size(), static_cast<size_t>(mesh.elementCount() - before));
}

TEST(AdaptiveRefinement, MinimumAreaIsNeverUndercut) {
  PatchMesh mesh = unitSquare(1.0 / 16);
  const double minArea = 1.0 / 64;
  for (int pass = 0; pass < 6; ++pass) {
    const auto values =
        sampled(mesh, [](const Eigen::Vector3d& c) { return c.x() < 0.37 ? 1.0 : 0.1; });
    const auto selected = selectForRefinement(mesh, values, {}, {0.1, minArea, 0});
    refineElements(mesh, selected, {0.1, minArea, 0}, 1 << 20);
  }
  for (int e = 0; e < mesh.elementCount(); ++e) EXPECT_GE(mesh.area(e), 0.5 * minArea * (1 - 1e-9));
}

TEST(AdaptiveRefinement, TargetsGrowGeometricallyToTheBudget) {
  EXPECT_EQ(refinementTarget(100, 800, 2, 3), 800);
  EXPECT_EQ(refinementTarget(100, 800, 0, 3), 200);
  EXPECT_EQ(refinementTarget(100, 800, 1, 3), 400);
  EXPECT_EQ(refinementTarget(100, 50, 0, 3), 100);  // a budget below the start refines nothing
}

// A field sampled at each element's 3 Gauss points (barycentric 2/3, 1/6, 1/6).
template <class Field>
std::vector<std::array<double, 3>> sampledAtGaussPoints(const PatchMesh& mesh, Field field) {
  std::vector<std::array<double, 3>> values(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto c = mesh.corners(e);
    for (int k = 0; k < 3; ++k)
      values[e][k] = field((4 * c[k] + c[(k + 1) % 3] + c[(k + 2) % 3]) / 6);
  }
  return values;
}

TEST(AdaptiveRefinement, GaussPointValuesShowASteepLinearFieldExactlyBordersIncluded) {
  // The field that the element-mean estimate flags at the borders (one-sided means) is shown
  // exactly from the Gauss points, so the point estimate is zero everywhere and nothing is split.
  const PatchMesh mesh = unitSquare(1.0 / 256);
  const auto values =
      sampledAtGaussPoints(mesh, [](const Eigen::Vector3d& c) { return 1.0 + 10.0 * c.x(); });
  for (double error : displayedPointError(mesh, values)) EXPECT_LT(error, 1e-9);
  EXPECT_TRUE(selectForRefinement(mesh, values, {}, {0.01, 0, 0}).empty());
}

TEST(AdaptiveRefinement, GaussPointEstimateSeesCurvatureAndShrinksWithTheSquareOfTheSize) {
  // L = 1 + 4 (x − 0.5)²: the planes of neighbouring elements disagree by about h²·L'' at their
  // shared vertices. Halving the element size (a quarter of the area) divides it by about 4.
  auto field = [](const Eigen::Vector3d& c) { return 1.0 + 4.0 * (c.x() - 0.5) * (c.x() - 0.5); };
  auto largest = [&](double area) {
    const PatchMesh mesh = unitSquare(area);
    double worst = 0;
    for (double error : displayedPointError(mesh, sampledAtGaussPoints(mesh, field)))
      worst = std::max(worst, error);
    return worst;
  };
  const double coarse = largest(1.0 / 64), fine = largest(1.0 / 256);
  EXPECT_GT(coarse, 1e-3);
  EXPECT_GT(coarse / fine, 3.0);
  EXPECT_LT(coarse / fine, 5.0);
}

TEST(AdaptiveRefinement, GaussPointEstimateRefinesAStepAlongItsLineOnly) {
  const PatchMesh mesh = unitSquare(1.0 / 64);
  const double h = std::sqrt(2.0 / 64);
  const auto values =
      sampledAtGaussPoints(mesh, [](const Eigen::Vector3d& c) { return c.x() < 0.37 ? 1.0 : 0.1; });
  const std::vector<int> selected = selectForRefinement(mesh, values, {}, {0.1, 0, 0});
  ASSERT_FALSE(selected.empty());
  for (int e : selected)
    EXPECT_LT(std::fabs(mesh.centroid(e).x() - 0.37), 1.5 * h) << "element " << e;
}

}  // namespace
}  // namespace rad
