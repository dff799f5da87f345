// One light of many (lighting/light_choice.h) and the emitters' power (power_distribution.h):
// unbiased by construction, checked against the sums they stand for.
#include <gtest/gtest.h>

#include "radiosity/lighting/light_choice.h"
#include "radiosity/lighting/power_distribution.h"

namespace rad {
namespace {

std::vector<Light> lamps() {
  std::vector<Light> lights;
  for (int k = 0; k < 7; ++k) {
    Light l;
    l.type = k % 2 ? LightType::Spot : LightType::Point;
    l.position = {k - 3.0, 2 + 0.3 * k, 0.5 * k};
    l.direction = {0, -1, 0};
    l.cosOuter = std::cos(1.2);
    l.cosInner = std::cos(0.6);
    l.intensity = {1.0 + k, 2.0, 3.0 - 0.3 * k};
    lights.push_back(l);
  }
  return lights;
}

// Every choice's estimate has the same luminance, the sum's (the choice is in proportion to it),
// so its mean over u is the lights' sum per channel within the discretisation of u: with N
// midpoints each light's share of [0, 1) holds its probability × N of them ± 1, an error of at
// most (lights + 1) / N of the largest estimate.
TEST(LightChoice, ChoiceWeightedByItsProbabilityIsTheSum) {
  const std::vector<Light> lights = lamps();
  std::vector<const Light*> pointers;
  for (const Light& l : lights) pointers.push_back(&l);
  const Eigen::Vector3d x(0.2, 0, 0.4), n(0, 1, 0);
  Rgb sum;
  for (const Light& l : lights) sum += unshadowedIrradiance(l, x, n);
  const int samples = 20000;
  Rgb mean;
  double largest = 0;
  for (int i = 0; i < samples; ++i) {
    const LightChoice c = chooseLight(pointers, x, n, (i + 0.5) / samples);
    ASSERT_TRUE(c.sample.found());
    const Rgb estimate = c.sample.irradiance * c.weight;
    EXPECT_NEAR(estimate.luminance(), sum.luminance(), 1e-12 * sum.luminance());
    largest = std::max(largest, estimate.maxComponent());
    mean += estimate / samples;
  }
  const double bound = (lights.size() + 1.0) / samples * largest;
  EXPECT_NEAR(mean.r, sum.r, bound);
  EXPECT_NEAR(mean.g, sum.g, bound);
  EXPECT_NEAR(mean.b, sum.b, bound);
}

TEST(LightChoice, NoLightReachingThePointChoosesNothing) {
  const std::vector<Light> lights = lamps();
  std::vector<const Light*> pointers;
  for (const Light& l : lights) pointers.push_back(&l);
  // Facing down, under every lamp: all behind the surface.
  EXPECT_FALSE(chooseLight(pointers, {0, 0, 0}, {0, -1, 0}, 0.5).sample.found());
}

TEST(PowerDistribution, PicksInProportionAndNeverAZeroWeight) {
  const PowerDistribution power({2, 0, 6, 2});
  EXPECT_DOUBLE_EQ(power.total(), 10);
  EXPECT_DOUBLE_EQ(power.probability(0), 0.2);
  EXPECT_DOUBLE_EQ(power.probability(1), 0.0);
  EXPECT_DOUBLE_EQ(power.probability(2), 0.6);
  std::vector<int> picks(4, 0);
  const int n = 1000;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    const size_t k = power.pick(u);
    ++picks[k];
    const double r = power.rescaled(u, k);
    EXPECT_GE(r, 0.0);
    EXPECT_LT(r, 1.0);
  }
  EXPECT_EQ(picks[0], 200);
  EXPECT_EQ(picks[1], 0);
  EXPECT_EQ(picks[2], 600);
  EXPECT_EQ(picks[3], 200);
  EXPECT_EQ(power.pick(std::nextafter(1.0, 0.0)), 3u);
  EXPECT_DOUBLE_EQ(emitterPower(2, {1, 2, 3}), 12);
}

}  // namespace
}  // namespace rad
