// Element-to-patch form factors (point-to-polygon + shadow rays) against Howell's catalogue.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "radiosity/formfactors/analytic_patch_shots.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "tests/support/analytic_form_factors.h"

namespace rad {
namespace {

// Area-weighted patch-to-patch factor from element-to-shooter factors: F_PQ = Σ_{e∈P} A_e F_eQ /
// A_P, where Q is the union of the shooters of input polygon `to`.
double patchToPatch(const PatchMesh& mesh, const AnalyticPatchShots& shots, int from, int to) {
  std::vector<int> targetShooters;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (mesh.patch(e) == to) targetShooters.push_back(mesh.shooter(e));
  std::sort(targetShooters.begin(), targetShooters.end());
  targetShooters.erase(std::unique(targetShooters.begin(), targetShooters.end()),
                       targetShooters.end());
  double sum = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.patch(e) != from) continue;
    for (int s : targetShooters) sum += mesh.area(e) * shots.elementToShooter(e, s);
  }
  return sum / mesh.patchArea(from);
}

PatchMesh meshed(std::vector<Eigen::Vector3d> p, std::vector<PatchPolygon> polygons,
                 double patchArea, double elementArea) {
  PatchMesh mesh(p, polygons);
  mesh.subdivideUniform(patchArea);
  mesh.markShooters();
  mesh.subdivideUniform(elementArea);
  return mesh;
}

TEST(AnalyticPatchShots, ParallelSquaresWithinHalfAPercent) {
  const PatchMesh mesh = meshed(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}}, 0.1, 0.01);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 4, 1});
  EXPECT_NEAR(patchToPatch(mesh, shots, 0, 1), 0.199825, 0.005 * 0.199825);
}

TEST(AnalyticPatchShots, PerpendicularSquaresSharingAnEdgeWithinHalfAPercent) {
  const PatchMesh mesh = meshed({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 1}, {0, 0, 1}},
                                {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 1}}, 0.1, 0.005);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 4, 1});
  const double exact = reference::perpendicularRectangles(1, 1, 1);
  EXPECT_NEAR(patchToPatch(mesh, shots, 0, 1), exact, 0.005 * exact);
  EXPECT_NEAR(patchToPatch(mesh, shots, 1, 0), exact, 0.005 * exact);
}

TEST(AnalyticPatchShots, PowerFractionsAreReciprocalToTheReceiverFactors) {
  const PatchMesh mesh = meshed(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}}, 0.2, 0.05);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {1, 4, 1});
  const int s = mesh.shooter(mesh.elementCount() - 1);
  const FormFactorRow& row = shots.powerFractions(s);
  ASSERT_FALSE(row.targets.empty());
  for (size_t k = 0; k < row.targets.size(); ++k) {
    const int j = row.targets[k];
    EXPECT_NEAR(row.values[k], mesh.area(j) * shots.elementToShooter(j, s) / mesh.shooterArea(s),
                1e-15);
  }
  // A shooter sends nothing to its own elements.
  for (int j : row.targets) EXPECT_NE(mesh.shooter(j), s);
}

TEST(AnalyticPatchShots, PointFactorsAreThePointToPolygonFactorsAtTheGaussPoints) {
  // Nothing in the way: each receiver point's factor is the exact point-to-polygon factor there
  // (visibility 1), in the order of the element's corners, and the element's factor is their mean.
  const PatchMesh mesh = meshed(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}}, 0.2, 0.05);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 4, 1});
  const int s = mesh.shooter(mesh.elementCount() - 1);
  const auto source = mesh.shooterCorners(s);
  const std::vector<Eigen::Vector3d> polygon(source.begin(), source.end());
  shots.powerFractions(s);
  int compared = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.patch(e) != 0) continue;
    const auto c = mesh.corners(e);
    const auto atPoints = shots.elementToShooterAtPointsCached(e, s);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d x = (4 * c[k] + c[(k + 1) % 3] + c[(k + 2) % 3]) / 6;
      EXPECT_NEAR(atPoints[k], pointToPolygonFormFactor(x, mesh.normal(e), polygon),
                  1e-6 * atPoints[k]);
    }
    EXPECT_NEAR((atPoints[0] + atPoints[1] + atPoints[2]) / 3, shots.elementToShooter(e, s),
                1e-6 * atPoints[0]);
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

TEST(AnalyticPatchShots, BlockerReducesTheFactorAndMarksThePartialShadow) {
  // Receiver at z = 0 facing up, source at z = 2 facing down, and between them at z = 1 an opaque
  // plate covering x < 0.5 of the source's footprint: part of the exchange is blocked, none of it
  // is gained, and the receivers under the plate's edge see the source only in part.
  std::vector<Eigen::Vector3d> p = {{0, 0, 0},   {1, 0, 0},    {1, 1, 0},   {0, 1, 0},
                                    {0, 0, 2},   {1, 0, 2},    {1, 1, 2},   {0, 1, 2},
                                    {-5, -5, 1}, {0.5, -5, 1}, {0.5, 5, 1}, {-5, 5, 1}};
  std::vector<PatchPolygon> polygons = {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}, {{8, 11, 10, 9}, 2}};
  const PatchMesh blocked = meshed(p, polygons, 10, 0.05);
  const PatchMesh open = meshed(p, {polygons[0], polygons[1]}, 10, 0.05);
  RayCaster blockedRays(blocked), openRays(open);
  AnalyticPatchShots withBlocker(blocked, blockedRays, {3, 64, 1}),
      without(open, openRays, {3, 64, 1});
  const double a = patchToPatch(blocked, withBlocker, 0, 1), b = patchToPatch(open, without, 0, 1);
  // The plate's edge lies halfway (x = 0.5 at z = 1), so the ray from receiver x_r to source x_s
  // is blocked exactly when x_r + x_s < 1: mirroring both squares (x → 1 − x) swaps blocked and
  // open rays and keeps the kernel, so exactly half the exchange is blocked, a = b/2. The
  // estimate's noise: each receiver point's visible fraction of each shooter comes from 64
  // shadow rays, a binomial share whose variance is at most 1/(4·64) (stratification only
  // lowers it), weighted in a by w = A_e F_point / (3 A_P). So a's standard deviation is at
  // most σ = sqrt(Σ w² / 256), and a/b must be 0.5 within 4σ/b.
  std::set<int> sourceShooters;
  for (int e = 0; e < open.elementCount(); ++e)
    if (open.patch(e) == 1) sourceShooters.insert(open.shooter(e));
  double sumSquares = 0;
  for (int e = 0; e < open.elementCount(); ++e) {
    if (open.patch(e) != 0) continue;
    for (const int s : sourceShooters) {
      for (const double f : without.elementToShooterAtPointsCached(e, s)) {
        const double w = open.area(e) * f / (3 * open.patchArea(0));
        sumSquares += w * w;
      }
    }
  }
  const double sigma = std::sqrt(sumSquares / (4 * 64));
  std::printf("blocked / open %.5f, 4 sigma %.5f\n", a / b, 4 * sigma / b);
  ASSERT_GT(sigma, 0);
  EXPECT_NEAR(a / b, 0.5, 4 * sigma / b);
  int partial = 0;
  for (int e = 0; e < blocked.elementCount(); ++e)
    partial += blocked.patch(e) == 0 && withBlocker.partlyShadowed()[e];
  EXPECT_GT(partial, 0);
  for (int e = 0; e < open.elementCount(); ++e) EXPECT_FALSE(without.partlyShadowed()[e]);
}

TEST(AnalyticPatchShots, ShadowEdgeBetweenTheReceiverPointsIsMarked) {
  // A small source (2 cm) at z = 2 centred over x = 0.5, and at z = 1 a plate covering x < 0.5:
  // its shadow edge on the receiver is at x = 0.5, with a penumbra 2 cm wide. The receiver square
  // is two elements whose Gauss points lie at least 0.16 from that line, so each point sees the
  // source wholly or not at all; the elements are still crossed by the edge and must be marked.
  std::vector<Eigen::Vector3d> p = {
      {0, 0, 0},       {1, 0, 0},       {1, 1, 0},   {0, 1, 0},    {0.49, 0.49, 2}, {0.51, 0.49, 2},
      {0.51, 0.51, 2}, {0.49, 0.51, 2}, {-5, -5, 1}, {0.5, -5, 1}, {0.5, 5, 1},     {-5, 5, 1}};
  std::vector<PatchPolygon> polygons = {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}, {{8, 11, 10, 9}, 2}};
  const PatchMesh blocked = meshed(p, polygons, 100, 100);
  const PatchMesh open = meshed(p, {polygons[0], polygons[1]}, 100, 100);
  RayCaster blockedRays(blocked), openRays(open);
  AnalyticPatchShots withBlocker(blocked, blockedRays, {3, 16, 1}),
      without(open, openRays, {3, 16, 1});
  for (const auto* pair : {&withBlocker, &without}) {
    const PatchMesh& mesh = pair == &withBlocker ? blocked : open;
    for (int e = 0; e < mesh.elementCount(); ++e)
      for (int f = 0; f < mesh.elementCount(); ++f)
        if (mesh.patch(e) == 0 && mesh.patch(f) == 1) {
          EXPECT_GT(pair->elementToShooter(e, mesh.shooter(f)), 0);
        }
  }
  for (int e = 0; e < blocked.elementCount(); ++e)
    if (blocked.patch(e) == 0) {
      EXPECT_TRUE(withBlocker.partlyShadowed()[e]) << "element " << e;
    }
  for (int e = 0; e < open.elementCount(); ++e) EXPECT_FALSE(without.partlyShadowed()[e]);
}

TEST(AnalyticPatchShots, RowsUpdatedAfterRefinementEqualFreshRows) {
  // Rows computed before a refinement, updated for the changed elements only, must equal rows
  // computed from scratch on the refined mesh (same streams per receiver and shooter).
  std::vector<Eigen::Vector3d> p = {{0, 0, 0},   {1, 0, 0},    {1, 1, 0},   {0, 1, 0},
                                    {0, 0, 2},   {1, 0, 2},    {1, 1, 2},   {0, 1, 2},
                                    {-5, -5, 1}, {0.5, -5, 1}, {0.5, 5, 1}, {-5, 5, 1}};
  PatchMesh mesh = meshed(p, {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}, {{8, 11, 10, 9}, 2}}, 0.5, 0.1);
  RayCaster rays(mesh);
  AnalyticPatchShots updated(mesh, rays, {3, 8, 1});
  for (int s = 0; s < mesh.shooterCount(); ++s) updated.powerFractions(s);
  const int before = mesh.elementCount();
  std::vector<std::array<int, 3>> corners(before);
  for (int e = 0; e < before; ++e) corners[e] = mesh.cornerVertices(e);
  for (int e = 0; e < before; e += 3) mesh.bisect(e);
  std::vector<int> changed;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (e >= before || mesh.cornerVertices(e) != corners[e]) changed.push_back(e);
  ASSERT_GT(mesh.elementCount(), before);
  ASSERT_LT(changed.size(), static_cast<size_t>(mesh.elementCount()));
  updated.meshChanged(changed);
  AnalyticPatchShots fresh(mesh, rays, {3, 8, 1});
  for (int s = 0; s < mesh.shooterCount(); ++s) {
    const FormFactorRow& a = updated.powerFractions(s);
    const FormFactorRow& b = fresh.powerFractions(s);
    ASSERT_EQ(a.targets, b.targets) << "shooter " << s;
    for (size_t k = 0; k < a.values.size(); ++k) EXPECT_NEAR(a.values[k], b.values[k], 1e-14);
    ASSERT_EQ(a.points.size(), a.targets.size());
    ASSERT_EQ(b.points.size(), b.targets.size());
    for (size_t k = 0; k < a.points.size(); ++k)
      EXPECT_EQ(a.points[k], b.points[k]) << "shooter " << s;
  }
}

TEST(AnalyticPatchShots, BackToBackPairsGetNoRays) {
  // Two squares facing away from each other: no energy, and not a single ray spent.
  const PatchMesh mesh = meshed(
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{{0, 3, 2, 1}, 0}, {{4, 5, 6, 7}, 1}}, 0.25, 0.1);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 16, 1});
  for (int s = 0; s < mesh.shooterCount(); ++s)
    EXPECT_TRUE(shots.powerFractions(s).targets.empty());
  EXPECT_EQ(shots.raysCast(), 0u);
}

TEST(AnalyticPatchShots, RowsOfAClosedBoxSumToOneWithinTheQuadratureError) {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const PatchMesh mesh = meshed(p,
                                {{{0, 1, 2, 3}, 0},
                                 {{4, 7, 6, 5}, 0},
                                 {{0, 4, 5, 1}, 0},
                                 {{3, 2, 6, 7}, 0},
                                 {{0, 3, 7, 4}, 0},
                                 {{1, 5, 6, 2}, 0}},
                                0.1, 0.02);
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 4, 1});
  const auto f = shots.gatheringMatrix();
  double worst = 0, mean = 0;
  for (int i = 0; i < f.rows(); ++i) {
    const double sum = f.row(i).sum();
    worst = std::max(worst, std::fabs(sum - 1));
    mean += sum / f.rows();
  }
  // Every element sees the whole inside of the box; only the 3-point rule's error remains,
  // largest for elements in a corner.
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace rad
