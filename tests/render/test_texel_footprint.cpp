// A lightmap texel's footprint on its element (render/texel_footprint.h) and the final gather
// spread over it: the points cover the texel uniformly and stay on the element, and under a hard
// sun a texel that a shadow edge crosses holds the lit fraction of its area, where its centre
// alone would say lit or dark.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "radiosity/core/rng.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/texel_footprint.h"
#include "tests/support/test_scenes.h"

namespace rad {
namespace {

using Vec2 = Eigen::Vector2d;

Vec2 texelPoint(const std::array<Vec2, 3>& t, const Eigen::Vector3d& b) {
  return b[0] * t[0] + b[1] * t[1] + b[2] * t[2];
}

TEST(TexelFootprint, PointsCoverAnInnerTexelUniformly) {
  // A triangle ten texels across; the texel (4, 3) lies wholly inside it.
  const std::array<Vec2, 3> t{Vec2(1.2, 1.7), Vec2(11.9, 2.3), Vec2(3.1, 12.4)};
  const Vec2 centre(4.5, 3.5);
  // The centre's barycentrics (the affine map the footprint inverts).
  const Vec2 e1 = t[1] - t[0], e2 = t[2] - t[0], d = centre - t[0];
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  const double b1 = (d.x() * e2.y() - d.y() * e2.x()) / det,
               b2 = (e1.x() * d.y() - e1.y() * d.x()) / det;
  const TexelFootprint f = TexelFootprint::of(t, {1 - b1 - b2, b1, b2});
  EXPECT_FALSE(f.isPoint());
  EXPECT_LT((texelPoint(t, f.at(0.5, 0.5)) - centre).norm(), 1e-12);
  Rng rng(7);
  for (int k = 0; k < 1000; ++k) {
    const double u = rng.uniform(), v = rng.uniform();
    const Eigen::Vector3d b = f.at(u, v);
    EXPECT_NEAR(b.sum(), 1.0, 1e-12);
    // Exactly the point (x + u, y + v) of the texel: no mirroring inside the triangle.
    EXPECT_LT((texelPoint(t, b) - Vec2(4 + u, 3 + v)).norm(), 1e-12) << u << " " << v;
  }
}

TEST(TexelFootprint, PointsOfATexelPastTheEdgeStayOnTheElement) {
  // A sliver a fraction of a texel wide, and texels reaching far past it: every point is on it.
  const std::array<Vec2, 3> t{Vec2(5.0, 5.0), Vec2(5.3, 5.1), Vec2(5.1, 5.4)};
  Rng rng(11);
  for (const Eigen::Vector3d& centre :
       {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0.2, 0.3, 0.5), Eigen::Vector3d(0, 0.5, 0.5)}) {
    const TexelFootprint f = TexelFootprint::of(t, centre);
    for (int k = 0; k < 2000; ++k) {
      const Eigen::Vector3d b = f.at(rng.uniform(), rng.uniform());
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(b[c], -1e-12);
        EXPECT_LE(b[c], 1 + 1e-12);
      }
      EXPECT_NEAR(b.sum(), 1.0, 1e-12);
    }
  }
  EXPECT_DOUBLE_EQ(TexelFootprint::mirrorInto(-0.25, 1), 0.25);
  EXPECT_DOUBLE_EQ(TexelFootprint::mirrorInto(1.25, 1), 0.75);
  EXPECT_DOUBLE_EQ(TexelFootprint::mirrorInto(2.5, 1), 0.5);
  EXPECT_DOUBLE_EQ(TexelFootprint::mirrorInto(0.3, 0), 0.0);
}

TEST(TexelFootprint, ATriangleOfNoAreaInTexelSpaceGivesItsCentreAlone) {
  // Scene UVs may collapse a face to a line: no steps to invert, so the texel is its centre.
  const std::array<Vec2, 3> line{Vec2(1, 1), Vec2(2, 2), Vec2(3, 3)};
  const TexelFootprint f = TexelFootprint::of(line, {0.2, 0.3, 0.5});
  EXPECT_TRUE(f.isPoint());
  EXPECT_LT((f.at(0.9, 0.1) - Eigen::Vector3d(0.2, 0.3, 0.5)).norm(), 1e-15);
}

const Rgb kRho{0.5, 0.4, 0.3};
const Rgb kSun{3.0, 2.0, 1.0};  // W/m² on a plane facing it

// A floor (y = 0) under a hard sun straight above, and a roof at y = 0.5 over x < 0 (facing up:
// its underside is a back face, which absorbs), so the floor's shadow edge is the line x = 0 and
// no light reaches the floor but the sun's.
Scene shadowEdgeScene() {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = kSun;
  Scene scene = testing::greyScene(kRho, {sun});
  // Off the origin, so no mesh line follows the shadow edge.
  testing::addPolygon(scene,
                      {{-1.13, 0, -0.91}, {-1.13, 0, 1.07}, {0.87, 0, 1.07}, {0.87, 0, -0.91}});
  testing::addPolygon(scene, {{-3, 0.5, -3}, {-3, 0.5, 3}, {0, 0.5, 3}, {0, 0.5, -3}});
  return scene;
}

// Barycentrics of p on the triangle c (p in its plane).
Eigen::Vector3d barycentricOf(const std::array<Eigen::Vector3d, 3>& c, const Eigen::Vector3d& p) {
  const Eigen::Vector3d e1 = c[1] - c[0], e2 = c[2] - c[0], d = p - c[0];
  const double a = e1.dot(e1), b = e1.dot(e2), cc = e2.dot(e2), d1 = d.dot(e1), d2 = d.dot(e2);
  const double det = a * cc - b * b;
  const double b1 = (cc * d1 - b * d2) / det, b2 = (a * d2 - b * d1) / det;
  return {1 - b1 - b2, b1, b2};
}

TEST(FinalGatherFootprint, ATexelAcrossAHardShadowEdgeHoldsItsLitFraction) {
  SolveOptions options;
  options.targetElements = 40;
  options.raysPerElement = 64;
  options.threads = 2;
  const SolveResult solved = solveScene(shadowEdgeScene(), options);
  const PatchMesh& mesh = *solved.solution.mesh;
  const RayCaster caster(mesh, solved.solution.scene);
  const RenderScene view(solved.solution.scene, mesh, caster);
  const FinalGather gather(view, solved.solution.radiosity, FinalGatherOptions{64, 64});

  // A floor element with a square texel of side s on it, axes along x and z, wholly inside its
  // incircle, centred at x = 0.1 s: 40% of the texel lies at x < 0, in the roof's shadow.
  int element = -1;
  Eigen::Vector3d centre;
  double side = 0;
  for (int e = 0; e < mesh.elementCount() && element < 0; ++e) {
    const auto c = mesh.corners(e);
    if (mesh.normal(e).y() < 0.99 || std::abs(c[0].y()) > 1e-9) continue;
    const double a = (c[1] - c[2]).norm(), b = (c[0] - c[2]).norm(), d = (c[0] - c[1]).norm();
    const Eigen::Vector3d incentre = (a * c[0] + b * c[1] + d * c[2]) / (a + b + d);
    const double r = 2 * mesh.area(e) / (a + b + d);
    const double s = 0.5 * r;
    const Eigen::Vector3d q(0.1 * s, 0, incentre.z());
    if ((q - incentre).norm() + s / std::sqrt(2.0) < 0.95 * r) {
      element = e;
      centre = q;
      side = s;
    }
  }
  ASSERT_GE(element, 0) << "no floor element across the shadow edge";
  const auto c = mesh.corners(element);
  const Eigen::Vector3d b = barycentricOf(c, centre);
  TexelFootprint footprint;
  footprint.centre = b;
  footprint.perX = barycentricOf(c, centre + Eigen::Vector3d(side, 0, 0)) - b;
  footprint.perY = barycentricOf(c, centre + Eigen::Vector3d(0, 0, side)) - b;

  // The floor reflects ρ E/π where lit; the roof's underside absorbs what it sends up, so nothing
  // else arrives. Over the texel: 0.6 of that. The 64 points are n-rooks stratified across x, so
  // the lit count is 38 or 39 of 64, whatever the seed: within 1/64 of 0.6.
  for (uint64_t seed : {1u, 2u, 3u}) {
    Rng rng(seed), atCentre(seed);
    RayCounts counts;
    Rgb error;
    const Rgb spread = gather.outgoingRadiance(element, footprint, rng, counts, error);
    const Rgb point = gather.outgoingRadiance(element, b, atCentre, counts, error);
    for (int k = 0; k < 3; ++k) {
      const double lit = kRho[k] * kSun[k] / M_PI;
      EXPECT_NEAR(spread[k], 0.6 * lit, lit / 64 + 1e-9) << "seed " << seed << " channel " << k;
      EXPECT_NEAR(point[k], lit, 1e-9 * lit) << "the centre is lit";
    }
  }
}

}  // namespace
}  // namespace rad
