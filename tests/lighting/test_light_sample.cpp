// The lighting layer (lighting/light_sample.h): what is a delta light, and each area light's
// samples against closed forms — their mean irradiance, and the density they report against the
// density lightPdf gives the same direction (the MIS weights of every render rest on the two
// agreeing).
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/lighting/light_sample.h"
#include "radiosity/scene/light_shapes.h"

namespace rad {
namespace {

Light pointLight(const Eigen::Vector3d& at, const Rgb& intensity) {
  Light l;
  l.type = LightType::Point;
  l.position = at;
  l.intensity = intensity;
  return l;
}

Light sunOf(double diameterDegrees) {
  Light l = sunLight(Eigen::Vector3d(0.3, -1, 0.2).normalized(), {3, 2, 1});
  l.angularDiameterDegrees = diameterDegrees;
  return l;
}

// The mean of `sample(u1, u2).irradiance` over the midpoints of an m × m grid of strata.
template <typename F>
Rgb meanOverStrata(int m, F sample) {
  Rgb sum;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) sum += sample((i + 0.5) / m, (j + 0.5) / m).irradiance;
  return sum / (m * m);
}

TEST(LightSample, DeltaLightsArePointSpotAndTheHardSun) {
  Light spot = pointLight({0, 1, 0}, {1, 1, 1});
  spot.type = LightType::Spot;
  EXPECT_TRUE(isDeltaLight(pointLight({0, 1, 0}, {1, 1, 1})));
  EXPECT_TRUE(isDeltaLight(spot));
  EXPECT_TRUE(isDeltaLight(sunOf(0)));
  EXPECT_FALSE(isDeltaLight(sunOf(0.53)));
  EXPECT_FALSE(isDeltaLight(skyLight({1, 1, 1})));
}

// I cosθ / r², and E⊥ = I / r² whatever the surface: exact, pdf 1, and nothing from behind.
TEST(LightSample, PointLightIsInverseSquareCosine) {
  const Light lamp = pointLight({0, 2, 0}, {4, 8, 12});
  const Eigen::Vector3d x(1, 0, 0), n(0, 1, 0);
  const LightSample s = sampleLight(lamp, x, n, 0.3, 0.7);
  const double r2 = 5, cosTheta = 2 / std::sqrt(5.0);
  EXPECT_TRUE(s.delta);
  EXPECT_EQ(s.pdf, 1);
  EXPECT_NEAR(s.distance, std::sqrt(r2), 1e-15);
  EXPECT_NEAR(s.radiance.g, 8 / r2, 1e-15);
  EXPECT_NEAR(s.irradiance.b, 12 * cosTheta / r2, 1e-15);
  EXPECT_NEAR(unshadowedIrradiance(lamp, x, n).r, 4 * cosTheta / r2, 1e-15);
  EXPECT_FALSE(sampleLight(lamp, x, -n, 0.3, 0.7).found());
  EXPECT_EQ(lightPdf(lamp, n, s.direction), 0);  // no scattered ray can hit it
  EXPECT_TRUE(radianceAlong(lamp, s.direction).isZero());
}

// ∫ L (n·ω) dω over the disc = L π sin²h (n·axis) = E cos β exactly (the integrand is linear in
// ω, and cos α to the axis is uniform in the samples' first number, so the strata's midpoints
// integrate it exactly); the hard sun gives the same at its centre.
TEST(LightSample, SunDiscAveragesToItsIrradianceTimesTheCosine) {
  const Eigen::Vector3d x(0, 0, 0), n = Eigen::Vector3d(0.2, 1, -0.1).normalized();
  for (const double diameter : {0.0, 0.53, 5.0}) {
    const Light sun = sunOf(diameter);
    const Rgb mean =
        meanOverStrata(16, [&](double u1, double u2) { return sampleLight(sun, x, n, u1, u2); });
    const double cosBeta = n.dot(-sun.direction);
    EXPECT_NEAR(mean.r, 3 * cosBeta, 1e-12) << diameter;
    EXPECT_NEAR(unshadowedIrradiance(sun, x, n).g, 2 * cosBeta, 1e-15) << diameter;
  }
}

// A uniform sky: πL (1 + cos α)/2 on a plane tilted by α from up (the ground black). The cosine
// samples about n give πL where they point above the horizon, 0 below, so only the strata the
// horizon crosses are in error, each by at most πL / m²: fewer than 4m of them (the horizon's
// curve crosses each row and column of strata at most twice), so the bound is 4πL / m.
TEST(LightSample, UniformSkyAveragesToTheLuneIrradiance) {
  const Light sky = skyLight({1, 2, 3});
  const int m = 256;
  for (const double alphaDegrees : {0.0, 30.0, 90.0, 150.0}) {
    const double a = alphaDegrees * M_PI / 180;
    const Eigen::Vector3d n(std::sin(a), std::cos(a), 0);
    const Rgb mean = meanOverStrata(m, [&](double u1, double u2) {
      return sampleLight(sky, Eigen::Vector3d::Zero(), n, u1, u2);
    });
    const double expected = M_PI * (1 + std::cos(a)) / 2;
    EXPECT_NEAR(mean.r, expected, 4 * M_PI / m) << alphaDegrees;
    EXPECT_NEAR(skyIrradiance(sky, n).b, 3 * expected, 1e-12) << alphaDegrees;
  }
}

// The density a sample reports is the density lightPdf gives its direction, and what an escaped
// ray along it sees is the sample's radiance: for the sun's disc, the cosine-sampled sky and a
// map-sampled CIE clear sky.
TEST(LightSample, SamplesAgreeWithLightPdfAndRadianceAlong) {
  const Eigen::Vector3d x(0, 0, 0), n = Eigen::Vector3d(0.3, 1, 0.1).normalized();
  const Light lights[] = {sunOf(0.53), skyLight({1, 1, 1}),
                          cieClearSky({1, 1, 1}, Eigen::Vector3d(0.4, -1, 0.3).normalized())};
  for (const Light& light : lights)
    for (int k = 0; k < 64; ++k) {
      const LightSample s = sampleLight(light, x, n, (k % 8 + 0.37) / 8, (k / 8 + 0.61) / 8);
      if (!(s.pdf > 0)) continue;
      EXPECT_FALSE(s.delta);
      EXPECT_NEAR(lightPdf(light, n, s.direction), s.pdf, 1e-9 * s.pdf)
          << lightTypeName(light.type) << " " << k;
      const Rgb along = radianceAlong(light, s.direction);
      EXPECT_NEAR(along.g, s.radiance.g, 1e-12 * (1 + s.radiance.g)) << k;
    }
  // Off the sun's disc there is neither density nor radiance.
  const Light sun = sunOf(0.53);
  const Eigen::Vector3d away = Eigen::Vector3d(1, 1, 0).normalized();
  EXPECT_EQ(lightPdf(sun, n, away), 0);
  EXPECT_TRUE(radianceAlong(sun, away).isZero());
}

}  // namespace
}  // namespace rad
