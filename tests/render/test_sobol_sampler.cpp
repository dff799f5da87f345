// The pixel sampler: Owen-scrambled Sobol points must be (0,m,2)-nets for every power-of-two
// count (the property that stratifies pixels, lenses, shadow and gather rays), each point must be
// uniform (estimators stay unbiased), and a discontinuity must integrate with less variance than
// with independent points.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "radiosity/render/emitter_sampler.h"
#include "radiosity/render/sobol_sampler.h"

namespace rad {
namespace {

// Every elementary interval [i/2^a, (i+1)/2^a) × [j/2^b, (j+1)/2^b) with a + b = m holds exactly
// one of the 2^m points.
bool isNet(const std::vector<Point2>& points, int m) {
  for (int a = 0; a <= m; ++a) {
    const int b = m - a;
    std::set<std::pair<int, int>> cells;
    for (const Point2& p : points) {
      if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) return false;
      cells.insert({static_cast<int>(p.x * (1 << a)), static_cast<int>(p.y * (1 << b))});
    }
    if (static_cast<int>(cells.size()) != (1 << m)) return false;
  }
  return true;
}

TEST(SobolSampler, FirstPowerOfTwoPointsOfEveryDimensionFormANet) {
  Rng rng(1);
  for (uint64_t pixel : {0ull, 1ull, 977ull}) {
    for (int m = 0; m <= 8; ++m) {
      const int n = 1 << m;
      SobolSampler sampler(42, pixel, rng);
      std::vector<std::vector<Point2>> byDimension(5);
      for (int s = 0; s < n; ++s) {
        sampler.startSample(s);
        for (auto& points : byDimension) points.push_back(sampler.get2D());
      }
      for (size_t d = 0; d < byDimension.size(); ++d)
        EXPECT_TRUE(isNet(byDimension[d], m)) << "pixel " << pixel << " n " << n << " dim " << d;
    }
  }
}

TEST(SobolSampler, ArraysOfAllSamplesFormOneNet) {
  Rng rng(2);
  SobolSampler sampler(7, 123, rng);
  std::vector<Point2> all, array;
  for (int s = 0; s < 16; ++s) {  // 16 samples × 4 gather rays = 64 points
    sampler.startSample(s);
    sampler.get2D();  // a pixel dimension first, as the renderer draws
    sampler.get2DArray(4, array);
    all.insert(all.end(), array.begin(), array.end());
  }
  EXPECT_TRUE(isNet(all, 6));
}

TEST(SobolSampler, EachPointIsUniformOverKeys) {
  // The mean and the second moment of x and y over independent scrambles: 1/2 and 1/3 within 4σ.
  constexpr int kKeys = 20000;
  for (uint32_t index : {0u, 1u, 5u, 1000u}) {
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int k = 0; k < kKeys; ++k) {
      const Point2 p = SobolSampler::point(index, streamKey(3, k));
      sx += p.x;
      sy += p.y;
      sxx += p.x * p.x;
      syy += p.y * p.y;
      sxy += p.x * p.y;
    }
    const double sigmaMean = std::sqrt(1.0 / 12 / kKeys), sigmaSquare = std::sqrt(4.0 / 45 / kKeys);
    EXPECT_NEAR(sx / kKeys, 0.5, 4 * sigmaMean) << index;
    EXPECT_NEAR(sy / kKeys, 0.5, 4 * sigmaMean) << index;
    EXPECT_NEAR(sxx / kKeys, 1.0 / 3, 4 * sigmaSquare) << index;
    EXPECT_NEAR(syy / kKeys, 1.0 / 3, 4 * sigmaSquare) << index;
    EXPECT_NEAR(sxy / kKeys, 0.25, 4 * sigmaMean) << index;  // x and y independent
  }
}

TEST(SobolSampler, SlantedEdgeHasLessVarianceThanIndependentPoints) {
  // Area below the line y = 0.3 + 0.37 x in the unit square (0.485), estimated with 64 points.
  // Independent points: variance p(1−p)/64. A scrambled net's error on an edge falls as n^-1.5:
  // about 8× less here; asking for 3× leaves room for the spread of the variance estimate itself.
  constexpr int kPoints = 64, kTrials = 4000;
  const double p = 0.3 + 0.37 / 2;
  double sum = 0, sum2 = 0;
  for (int t = 0; t < kTrials; ++t) {
    double inside = 0;
    for (uint32_t i = 0; i < kPoints; ++i) {
      const Point2 q = SobolSampler::point(i, streamKey(9, t));
      inside += q.y < 0.3 + 0.37 * q.x;
    }
    const double estimate = inside / kPoints;
    sum += estimate;
    sum2 += estimate * estimate;
  }
  const double mean = sum / kTrials, variance = sum2 / kTrials - mean * mean;
  const double independent = p * (1 - p) / kPoints;
  EXPECT_NEAR(mean, p, 4 * std::sqrt(independent / kTrials));  // unbiased
  EXPECT_LT(variance, independent / 3);
}

}  // namespace
}  // namespace rad
