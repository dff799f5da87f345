// The environment map (scene/environment_map.h): its orientation against Blender's
// equirectangular convention, its importance sampling (the density integrates to 1, each sample
// lies in the texel the density names, the estimator is unbiased), its irradiance table, and the
// CIE clear sky's formula (scene/light_shapes.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "radiosity/core/rng.h"
#include "radiosity/scene/environment_map.h"
#include "radiosity/scene/light_shapes.h"
#include "radiosity/scene/lights.h"

namespace rad {
namespace {

// Cycles' direction_to_equirectangular (kernel/geom, range (−2π, π, −π, π)) for Z up, written
// out: u = (atan2(y, x) − π) / (−2π), v = (acos z − π) / (−π), v up from the image's bottom.
Eigen::Vector2d blenderUv(const Eigen::Vector3d& d) {
  return {(std::atan2(d.y(), d.x()) - M_PI) / (-2 * M_PI), (std::acos(d.z()) - M_PI) / (-M_PI)};
}

Eigen::Vector3d randomDirection(Rng& rng) {
  const double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
  const double r = std::sqrt(1 - z * z);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

TEST(EnvironmentMap, FollowsBlendersEquirectangularConventionWithZUp) {
  const EnvironmentMap map(4, 2, std::vector<Rgb>(8), {0, 0, 1});
  Rng rng(1);
  for (int k = 0; k < 1000; ++k) {
    const Eigen::Vector3d d = randomDirection(rng);
    const Eigen::Vector2d ours = map.imagePosition(d), blender = blenderUv(d);
    EXPECT_NEAR(std::remainder(ours.x() - blender.x(), 1.0), 0, 1e-12) << d.transpose();
    EXPECT_NEAR(ours.y(), 1 - blender.y(), 1e-12) << d.transpose();  // t counts down from the top
    EXPECT_LT((map.direction(ours.x(), ours.y()) - d).norm(), 1e-12);
  }
  EXPECT_LT((map.direction(0.5, 0.5) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);   // centre
  EXPECT_LT((map.direction(0.25, 0.5) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);  // quarter
  EXPECT_LT((map.direction(0.3, 0) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-12);     // top row
}

// A Blender scene exported Y up (x, y, z) → (x, z, −y): the same image lands the same way.
TEST(EnvironmentMap, WithYUpMatchesABlenderSceneExportedYUp) {
  const EnvironmentMap map(4, 2, std::vector<Rgb>(8), {0, 1, 0});
  EXPECT_LT((map.direction(0.5, 0.5) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((map.direction(0.25, 0.5) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);
  Rng rng(2);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector3d b = randomDirection(rng), y(b.x(), b.z(), -b.y());
    const Eigen::Vector2d ours = map.imagePosition(y), blender = blenderUv(b);
    EXPECT_NEAR(std::remainder(ours.x() - blender.x(), 1.0), 0, 1e-12);
    EXPECT_NEAR(ours.y(), 1 - blender.y(), 1e-12);
  }
}

// A map of random texels, a few of them 1000× brighter.
EnvironmentMap randomMap(int width, int height, uint64_t seed) {
  Rng rng(seed);
  std::vector<Rgb> texels(static_cast<std::size_t>(width) * height);
  for (Rgb& t : texels) {
    t = {rng.uniform(), rng.uniform(), rng.uniform()};
    if (rng.uniform() < 0.05) t = t * 1000;
    if (rng.uniform() < 0.1) t = Rgb();
  }
  return EnvironmentMap(width, height, texels, Eigen::Vector3d(0.3, 1, 0.2).normalized());
}

TEST(EnvironmentMap, TheSolidAnglesAddUpToTheSphereAndTheDensityToOne) {
  const EnvironmentMap map = randomMap(24, 12, 3);
  double sphere = 0, total = 0;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      sphere += map.texelSolidAngle(y);
      const Eigen::Vector3d d = map.direction((x + 0.5) / map.width(), (y + 0.5) / map.height());
      total += map.pdf(d) * map.texelSolidAngle(y);  // the density is constant over a texel
    }
  EXPECT_NEAR(sphere, 4 * M_PI, 1e-12);
  EXPECT_NEAR(total, 1, 1e-12);
}

// Every sample lies in a texel of non-zero radiance with the density `pdf` names; the estimate
// Σ L(ω)/p(ω) / n of ∫ L dω (per channel) matches the exact Σ L Ω over the texels within 5σ (σ
// the standard error from the samples' own spread).
TEST(EnvironmentMap, SamplingIsUnbiasedForARandomMap) {
  const EnvironmentMap map = randomMap(32, 16, 4);
  Rgb exact;
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x)
      exact += map.texels()[static_cast<std::size_t>(y) * map.width() + x] * map.texelSolidAngle(y);
  Rng rng(5);
  const int n = 200000;
  Rgb sum, squares;
  for (int k = 0; k < n; ++k) {
    double pdf = 0;
    const Eigen::Vector3d d = map.sample(rng.uniform(), rng.uniform(), pdf);
    ASSERT_NEAR(d.norm(), 1, 1e-12);
    ASSERT_GT(pdf, 0);
    ASSERT_NEAR(map.pdf(d), pdf, 1e-9 * pdf);
    const Rgb v = map.radiance(d) / pdf;
    sum += v;
    squares += v * v;
  }
  for (int c = 0; c < 3; ++c) {
    const double mean = sum[c] / n, sigma = std::sqrt((squares[c] / n - mean * mean) / (n - 1));
    EXPECT_NEAR(mean, exact[c], 5 * sigma) << "channel " << c;
  }
}

TEST(EnvironmentMap, ABlackMapHasNoDensity) {
  const EnvironmentMap map(8, 4, std::vector<Rgb>(32), {0, 1, 0});
  double pdf = 1;
  map.sample(0.3, 0.7, pdf);
  EXPECT_EQ(pdf, 0);
  EXPECT_EQ(map.pdf({0, 1, 0}), 0);
  EXPECT_TRUE(map.irradiance({0, 1, 0}).isZero());
}

// ∫ L max(0, n·ω) dω for a constant map is πL for every normal; for one bright texel it is the
// texel's power times the cosine at its direction. The table sums blocks (here quarter texels) as
// point sources and interpolates bilinearly between normals Δ = 5.6° apart: the smooth πL within
// 1% (the quadrature's error; measured 0.03%), the single texel within Δ√2/4 =
// 3.5% of its power, the most a bilinear cell straddling the cosine's kink at the terminator can
// miss by (measured 2.4% over 20 000 normals).
TEST(EnvironmentMap, TheIrradianceTableMatchesConstantAndSingleTexelMaps) {
  const EnvironmentMap constant(64, 32, std::vector<Rgb>(64 * 32, Rgb(2, 2, 2)), {0, 1, 0});
  Rng rng(6);
  for (int k = 0; k < 50; ++k)
    EXPECT_NEAR(constant.irradiance(randomDirection(rng)).r, 2 * M_PI, 0.01 * 2 * M_PI);
  std::vector<Rgb> texels(64 * 32);
  texels[10 * 64 + 20] = Rgb(1000, 1000, 1000);
  const EnvironmentMap one(64, 32, texels, {0, 1, 0});
  const Eigen::Vector3d towards = one.direction(20.5 / 64, 10.5 / 32);
  const double power = 1000 * one.texelSolidAngle(10);
  for (int k = 0; k < 500; ++k) {
    const Eigen::Vector3d n = randomDirection(rng);
    EXPECT_NEAR(one.irradiance(n).r, power * std::max(0.0, n.dot(towards)), 0.035 * power);
  }
}

// The CIE clear sky's formula, written out independently of the code.
double clearSky(double theta, double gamma, double thetaSun) {
  const auto f = [](double x) {
    return 0.91 + 10 * std::exp(-3 * x) + 0.45 * std::cos(x) * std::cos(x);
  };
  return f(gamma) * (1 - std::exp(-0.32 / std::cos(theta))) / (f(thetaSun) * (1 - std::exp(-0.32)));
}

TEST(ClearSky, MatchesTheFormulaIsOneAtTheZenithAndZeroBelowTheHorizon) {
  const Eigen::Vector3d up(0, 1, 0);
  const Eigen::Vector3d toSun = Eigen::Vector3d(0.5, 0.6, -0.3).normalized();
  const double thetaSun = std::acos(toSun.dot(up));
  EXPECT_NEAR(cieClearSkyRatio(up, toSun, up), 1, 1e-12);
  Rng rng(7);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d d = randomDirection(rng);
    const double want =
        d.dot(up) > 0 ? clearSky(std::acos(d.dot(up)), std::acos(d.dot(toSun)), thetaSun) : 0;
    EXPECT_NEAR(cieClearSkyRatio(d, toSun, up), want, 1e-12 * std::max(1.0, want));
  }
}

// The sky is brightest around the sun and darkest some 70° to 90° away from it, in the sun's
// vertical plane on the far side of the zenith (89.5°, 79.5°, 69.5° for the sun at 20°, 45°,
// 70°): over a 1° grid of the sky, the brightest direction lies within 5° of the sun, the
// darkest between 60° and 100° from it.
TEST(ClearSky, IsBrightestNearTheSunAndDarkestAboutNinetyDegreesAway) {
  for (const double elevation : {20.0, 45.0, 70.0}) {
    const double e = elevation * M_PI / 180;
    const Light sky = cieClearSky({1, 1, 1}, {-std::cos(e), -std::sin(e), 0});
    const Eigen::Vector3d toSun = -sky.direction;
    double brightest = -1, darkest = 1e300, atBrightest = 0, atDarkest = 0;
    for (int i = 0; i < 89; ++i)
      for (int j = 0; j < 360; ++j) {
        const double theta = (i + 0.5) * M_PI / 180, phi = j * M_PI / 180;
        const Eigen::Vector3d d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                std::sin(theta) * std::sin(phi));
        const double l = skyRadiance(sky, d).r;
        const double gamma = std::acos(std::clamp(d.dot(toSun), -1.0, 1.0)) * 180 / M_PI;
        if (l > brightest) brightest = l, atBrightest = gamma;
        if (l < darkest) darkest = l, atDarkest = gamma;
      }
    EXPECT_LT(atBrightest, 5) << "sun at " << elevation << "°";
    EXPECT_GT(atDarkest, 60) << "sun at " << elevation << "°";
    EXPECT_LT(atDarkest, 100) << "sun at " << elevation << "°";
    EXPECT_GT(brightest, 3 * darkest);
  }
}

}  // namespace
}  // namespace rad
