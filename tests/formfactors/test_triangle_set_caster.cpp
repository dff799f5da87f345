// TriangleSetCaster, update's test of which rays pass through what moved: its distances must be
// those of an exact ray-triangle test in double precision, for rays that meet the set's box from
// every side, start inside it, run along an axis (direction components exactly 0) or pass just
// outside it — the slab test that spares most rays Embree's call must never reject a ray that
// meets a triangle.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "radiosity/visibility/triangle_set_caster.h"

namespace rad {
namespace {

using Triangle = std::array<Eigen::Vector3d, 3>;

// Distance along d (in units of |d|) to the triangle, Möller–Trumbore in double; infinity on a
// miss. `edge` receives the smallest barycentric coordinate of the hit (how close to an edge).
double exactDistance(const Triangle& t, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                     double& edge) {
  const Eigen::Vector3d e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Eigen::Vector3d p = d.cross(e2);
  const double det = e1.dot(p);
  edge = -1;
  if (std::abs(det) < 1e-14) return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d s = o - t[0];
  const double u = s.dot(p) / det;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = d.dot(q) / det;
  const double dist = e2.dot(q) / det;
  edge = std::min({u, v, 1 - u - v});
  if (edge < 0 || dist < 0) return std::numeric_limits<double>::infinity();
  return dist;
}

// The caster's distance for one ray, given in the caster's frame in double and cast to float
// as the form-factor rays are.
float distanceOf(const TriangleSetCaster& caster, const Eigen::Vector3d& o,
                 const Eigen::Vector3d& d) {
  const float origin[3] = {static_cast<float>(o.x()), static_cast<float>(o.y()),
                           static_cast<float>(o.z())};
  const float direction[3] = {static_cast<float>(d.x()), static_cast<float>(d.y()),
                              static_cast<float>(d.z())};
  const float* originPtr[3] = {&origin[0], &origin[1], &origin[2]};
  const float* directionPtr[3] = {&direction[0], &direction[1], &direction[2]};
  float distance = 0;
  caster.distances(1, originPtr, directionPtr, &distance);
  return distance;
}

TEST(TriangleSetCaster, DistancesAreTheExactFirstHitsForRaysFromEverywhere) {
  // A crate-like set far from the frame's centre (as a small edit in a large scene is).
  const Eigen::Vector3d centre(0.5, -0.2, 0.1), offset(40, 3, -25);
  std::vector<Triangle> set;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 24; ++k) {
    const Eigen::Vector3d a = offset + Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    set.push_back({a, a + 0.4 * Eigen::Vector3d(unit(rng), unit(rng), 0),
                   a + 0.4 * Eigen::Vector3d(0, unit(rng), unit(rng))});
  }
  const TriangleSetCaster caster(set, centre, 120.0);
  ASSERT_FALSE(caster.empty());

  int hits = 0, checked = 0, axisRays = 0;
  for (int r = 0; r < 40000; ++r) {
    // Origins around the box (some inside), aimed at a point near it or along an axis.
    const Eigen::Vector3d from = offset + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 6 -
                                 Eigen::Vector3d::Ones() * 2.5;
    Eigen::Vector3d d;
    if (r % 4 == 0) {
      d = Eigen::Vector3d::Zero();
      d[r / 4 % 3] = (r / 12) % 2 ? 1.0 : -1.0;
      ++axisRays;
    } else {
      const Eigen::Vector3d to = offset + Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 1.6 -
                                 Eigen::Vector3d::Ones() * 0.3;
      d = (to - from).normalized() * (0.5 + unit(rng));  // not unit length: distances scale
    }
    // The exact first hit; a ray that passes within float rounding of some triangle's edge
    // (smallest barycentric near 0, hit or not) may go either way, and is left out.
    double nearest = std::numeric_limits<double>::infinity();
    bool grazing = false;
    for (const Triangle& t : set) {
      double edge = 0;
      nearest = std::min(nearest, exactDistance(t, from, d, edge));
      grazing |= std::abs(edge) < 1e-4;
    }
    if (grazing) continue;
    const float got = distanceOf(caster, from - centre, d);
    ++checked;
    if (std::isfinite(nearest)) {
      ++hits;
      ASSERT_TRUE(std::isfinite(got)) << "ray " << r << " meets the set at " << nearest;
      EXPECT_NEAR(got, nearest, 1e-4 * (1 + nearest)) << "ray " << r;
    } else {
      EXPECT_FALSE(std::isfinite(got)) << "ray " << r << " misses the set, got " << got;
    }
  }
  // The mix is what the test is about: many hits, many misses, axis rays among them.
  EXPECT_GT(hits, 3000);
  EXPECT_GT(checked - hits, 3000);
  EXPECT_GT(axisRays, 5000);
}

// A millimetre triangle next to the frame's centre, seen from 50 m: the slab test's rounding
// then comes from the origins' coordinates, not the box's. Every ray must get the answer of a
// caster whose box is so wide that the slab test rejects nothing (Embree's own, in float).
TEST(TriangleSetCaster, ATinySetSeenFromAfarLosesNoRay) {
  const Eigen::Vector3d centre(0, 0, 0);
  const Triangle tiny{Eigen::Vector3d(0.001, 0.001, 0), Eigen::Vector3d(0.002, 0.001, 0),
                      Eigen::Vector3d(0.001, 0.002, 0.0005)};
  const TriangleSetCaster caster({tiny}, centre, 100.0), unboxed({tiny}, centre, 1e7);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int hits = 0;
  for (int r = 0; r < 200000; ++r) {
    const Eigen::Vector3d from =
        Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized() *
        (30 + 20 * unit(rng));
    const double a = unit(rng) * 1.4 - 0.2, b = unit(rng) * 1.4 - 0.2;
    const Eigen::Vector3d d = tiny[0] + a * (tiny[1] - tiny[0]) + b * (tiny[2] - tiny[0]) - from;
    const float got = distanceOf(caster, from - centre, d);
    const float expected = distanceOf(unboxed, from - centre, d);
    hits += std::isfinite(expected);
    ASSERT_EQ(std::isfinite(got), std::isfinite(expected)) << "ray " << r;
    if (std::isfinite(expected)) {
      ASSERT_EQ(got, expected) << "ray " << r;
    }
  }
  EXPECT_GT(hits, 50000);
}

TEST(TriangleSetCaster, AnEmptySetMeetsNothing) {
  const TriangleSetCaster caster({}, Eigen::Vector3d::Zero(), 1.0);
  EXPECT_TRUE(caster.empty());
  EXPECT_FALSE(
      std::isfinite(distanceOf(caster, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX())));
}

}  // namespace
}  // namespace rad
