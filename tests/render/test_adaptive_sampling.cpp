// Adaptive pixel sampling (`render --adaptive`): the allocation's rules on made-up spreads, then on
// the Cornell box that it stays unbiased, puts its samples on the light's outline and lowers the
// image's error for the same number of samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "radiosity/render/adaptive_allocation.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/image_renderer.h"
#include "tests/render/render_fixture.h"

namespace rad {
namespace {

// Unbiasedness rests on this: a pixel's count is the same whatever its own first-pass spread.
TEST(AdaptiveAllocation, APixelsCountIgnoresItsOwnSpread) {
  constexpr int kWidth = 7, kHeight = 5;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> spread(0.0, 2.0);
  std::vector<double> sigma(kWidth * kHeight);
  for (double& s : sigma) s = spread(random);
  for (size_t p = 0; p < sigma.size(); ++p) {
    std::vector<double> varied = sigma;
    varied[p] = 0;
    const int without = allocateAdaptiveSamples(varied, kWidth, kHeight, 10000, 1 << 20).extra[p];
    for (const double own : {0.5, 3.0, 100.0}) {
      varied[p] = own;
      EXPECT_EQ(allocateAdaptiveSamples(varied, kWidth, kHeight, 10000, 1 << 20).extra[p], without)
          << "pixel " << p << ", own spread " << own;
    }
  }
}

// A line of spread 10 across a field of spread 1: the line and the rows beside it (whose
// neighbours are on it) get 10 times the field's share; the total is the budget within the
// rounding and the leave-one-out sums; no spread anywhere shares evenly; the cap holds.
TEST(AdaptiveAllocation, SharesFollowTheNeighboursSpread) {
  constexpr int kWidth = 20, kHeight = 11, kLine = 5;
  std::vector<double> sigma(kWidth * kHeight, 1.0);
  for (int x = 0; x < kWidth; ++x) sigma[kLine * kWidth + x] = 10.0;
  const int64_t budget = 100000;
  const AdaptiveAllocation a = allocateAdaptiveSamples(sigma, kWidth, kHeight, budget, 1 << 20);
  auto at = [&](int x, int y) { return a.extra[y * kWidth + x]; };
  // Interior pixels: guide 10 within one row of the line, 1 farther away.
  EXPECT_NEAR(double(at(10, kLine)) / at(10, 0), 10.0, 0.1);
  EXPECT_NEAR(double(at(10, kLine - 1)) / at(10, 0), 10.0, 0.1);
  EXPECT_NEAR(double(at(10, kLine + 1)) / at(10, 0), 10.0, 0.1);
  EXPECT_EQ(at(10, kLine - 2), at(10, 0));
  EXPECT_NEAR(double(a.total), double(budget), 0.01 * budget);

  const AdaptiveAllocation even = allocateAdaptiveSamples(
      std::vector<double>(kWidth * kHeight, 0.0), kWidth, kHeight, 220 * 7, 1 << 20);
  for (int n : even.extra) EXPECT_EQ(n, 7);

  const AdaptiveAllocation capped = allocateAdaptiveSamples(sigma, kWidth, kHeight, budget, 600);
  for (int n : capped.extra) EXPECT_LE(n, 600);
  EXPECT_LT(capped.total, budget);
}

// The Cornell box at 64 × 64, the final gather on one solution: adaptive and uniform renders at
// the same mean samples per pixel, each as two independent halves (seeds), against a uniform
// render of 16 times the samples.
class AdaptiveCornell : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SolveOptions solve;
    solve.targetElements = 1500;
    solved_ = testing::solveForRender(
                  std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj", solve)
                  .release();
    camera_ = loadCamera(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.camera.json");
    camera_.width = camera_.height = 64;
    gather_ = new FinalGather(*solved_->view, solved_->solved.solution.radiosity, {1});
  }
  static void TearDownTestSuite() {
    delete gather_;
    delete solved_;
  }
  static RenderOutput render(int spp, bool adaptive, uint64_t seed) {
    RenderSettings settings;
    settings.samplesPerPixel = spp;
    settings.adaptive = adaptive;
    settings.seed = seed;
    settings.showProgress = false;
    return renderImage(camera_, *gather_, settings);
  }
  static testing::SolvedScene* solved_;
  static Camera camera_;
  static FinalGather* gather_;
};
testing::SolvedScene* AdaptiveCornell::solved_ = nullptr;
Camera AdaptiveCornell::camera_;
FinalGather* AdaptiveCornell::gather_ = nullptr;

// Unbiased: over 16 pairs of renders (independent seeds), the mean difference of the adaptive and
// uniform images' means is within 4 standard errors of 0 (the spread of the 16 differences; the
// per-pixel variances would overstate it, they ignore the Sobol points' stratification), and
// that bound is tight enough to see a bias of 0.5%.
TEST_F(AdaptiveCornell, ImageMeanMatchesUniformSampling) {
  constexpr int kPairs = 16;
  std::vector<Rgb> differences;
  Rgb meanUniform;
  for (uint64_t k = 0; k < kPairs; ++k) {
    const RenderOutput a = render(16, true, 21 + k), u = render(16, false, 121 + k);
    Rgb meanA, meanU;
    for (size_t p = 0; p < a.image.pixels.size(); ++p) {
      meanA += a.image.pixels[p] / double(a.image.pixels.size());
      meanU += u.image.pixels[p] / double(u.image.pixels.size());
    }
    differences.push_back(meanA - meanU);
    meanUniform += meanU / kPairs;
  }
  for (int c = 0; c < 3; ++c) {
    double mean = 0, squares = 0;
    for (const Rgb& d : differences) mean += d[c] / kPairs;
    for (const Rgb& d : differences) squares += (d[c] - mean) * (d[c] - mean);
    const double standardError = std::sqrt(squares / (kPairs - 1) / kPairs);
    std::printf("channel %d: adaptive - uniform %.4f%% of the mean (standard error %.4f%%)\n", c,
                100 * mean / meanUniform[c], 100 * standardError / meanUniform[c]);
    ASSERT_LT(4 * standardError, 0.005 * meanUniform[c]);
    EXPECT_LE(std::abs(mean), 4 * standardError) << "channel " << c;
  }
}

// Where the samples go and what they buy: the pixels along the light's outline take at least 4
// times the mean, and the image's relative RMSE against a 512-spp uniform render falls below 0.8
// of the uniform render's at the same 32 samples per pixel (both with the reference's noise left
// in, which only narrows the gap).
TEST_F(AdaptiveCornell, SamplesGoToTheLightsOutlineAndLowerTheError) {
  const RenderOutput reference = render(512, false, 31);
  const RenderOutput adaptive = render(32, true, 32), uniform = render(32, false, 33);
  ASSERT_EQ(adaptive.samples.size(), reference.image.pixels.size());
  const int w = camera_.width, h = camera_.height;
  double brightest = 0;
  for (const Rgb& p : reference.image.pixels) brightest = std::max(brightest, p.maxComponent());
  auto lit = [&](int x, int y) {
    return reference.image.at(x, y).maxComponent() > 0.5 * brightest;
  };
  double outline = 0, outlinePixels = 0, all = 0;
  for (int y = 1; y + 1 < h; ++y)
    for (int x = 1; x + 1 < w; ++x) {
      const int n = adaptive.samples[static_cast<size_t>(y) * w + x];
      all += n;
      if (lit(x, y) != lit(x + 1, y) || lit(x, y) != lit(x, y + 1)) {
        outline += n;
        ++outlinePixels;
      }
    }
  ASSERT_GT(outlinePixels, 10);
  const double outlineMean = outline / outlinePixels, mean = all / ((w - 2.0) * (h - 2.0));
  std::printf("outline pixels %.0f: mean %.1f samples, image mean %.1f\n", outlinePixels,
              outlineMean, mean);
  EXPECT_GE(outlineMean, 4 * mean);

  auto relativeRmse = [&](const ImageRgb& image) {
    double d2 = 0, sum = 0;
    for (size_t p = 0; p < image.pixels.size(); ++p) {
      const Rgb d = image.pixels[p] - reference.image.pixels[p];
      d2 += (d * d).sum();
      sum += reference.image.pixels[p].sum();
    }
    return std::sqrt(d2 / (3.0 * image.pixels.size())) / (sum / (3.0 * image.pixels.size()));
  };
  const double adaptiveError = relativeRmse(adaptive.image),
               uniformError = relativeRmse(uniform.image);
  std::printf("relative RMSE: adaptive %.4f, uniform %.4f (ratio %.2f)\n", adaptiveError,
              uniformError, adaptiveError / uniformError);
  EXPECT_LT(adaptiveError, 0.8 * uniformError);
}

}  // namespace
}  // namespace rad
