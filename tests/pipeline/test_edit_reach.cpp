// edit_reach.h's predicates against brute force: every ray that meets the edit's box must be
// reported as possibly meeting it (they are conservative), and a box the rays cannot reach must
// not be (they skip work).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "radiosity/pipeline/edit_reach.h"

namespace rad {
namespace {

// Whether the ray origin + t·d, t ≥ 0, meets the box (slab test).
bool rayMeetsBox(const Eigen::Vector3d& origin, const Eigen::Vector3d& d, const EditBox& box) {
  double near = 0, far = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-300) {
      if (origin[k] < box.lo[k] || origin[k] > box.hi[k]) return false;
      continue;
    }
    double t0 = (box.lo[k] - origin[k]) / d[k], t1 = (box.hi[k] - origin[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

TEST(EditReach, RaysAlongADirectionThatMeetTheBoxAreReported) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  int met = 0, ruledOut = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<Eigen::Vector3d, 3> corners;
    const Eigen::Vector3d at(2 * u(rng), 2 * u(rng), 2 * u(rng));
    for (auto& c : corners) c = at + 0.3 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    const Eigen::Vector3d centre(2 * u(rng), 2 * u(rng), 2 * u(rng));
    // Half the directions roughly toward the box, so that many rays meet it.
    const Eigen::Vector3d random(u(rng), u(rng), u(rng));
    const Eigen::Vector3d d =
        (trial % 2 ? random : (centre - at).normalized() + 0.4 * random).normalized();
    const Eigen::Vector3d half(0.05 + 0.3 * unit(rng), 0.05 + 0.3 * unit(rng),
                               0.05 + 0.3 * unit(rng));
    const EditBox box{centre - half, centre + half};
    const bool reported = raysAlongMayMeet(corners, d, box, 0);
    bool anyMeets = false;
    for (int k = 0; k < 64 && !anyMeets; ++k) {
      double s = unit(rng), t = unit(rng);
      if (s + t > 1) s = 1 - s, t = 1 - t;
      const Eigen::Vector3d p =
          corners[0] + s * (corners[1] - corners[0]) + t * (corners[2] - corners[0]);
      anyMeets = rayMeetsBox(p, d, box);
    }
    if (anyMeets) {
      ASSERT_TRUE(reported) << "trial " << trial;
      ++met;
    }
    ruledOut += !reported;
  }
  // Both kinds occur, and the predicate rules out a good share of the boxes no ray meets.
  EXPECT_GT(met, 100);
  EXPECT_GT(ruledOut, 500);
}

TEST(EditReach, ABoxBehindTheRaysOrBesideThemIsNotMet) {
  const std::array<Eigen::Vector3d, 3> floor = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                                Eigen::Vector3d(0, 1, 0)};
  const Eigen::Vector3d up(0, 0, 1);
  const EditBox above{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 1, 3)};
  const EditBox below{Eigen::Vector3d(0, 0, -3), Eigen::Vector3d(1, 1, -2)};
  const EditBox aside{Eigen::Vector3d(5, 5, 2), Eigen::Vector3d(6, 6, 3)};
  EXPECT_TRUE(raysAlongMayMeet(floor, up, above, 1e-4));
  EXPECT_FALSE(raysAlongMayMeet(floor, up, below, 1e-4));
  EXPECT_FALSE(raysAlongMayMeet(floor, up, aside, 1e-4));
  EXPECT_TRUE(raysAlongMayMeet(floor, Eigen::Vector3d(1, 1, 0.4), aside, 1e-4));
}

}  // namespace
}  // namespace rad
