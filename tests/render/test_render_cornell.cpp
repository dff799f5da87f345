// The radiosity final gather against the unbiased path tracer on the Cornell box, 64×64 from the
// published camera. Both are Monte Carlo estimates of the same image, so the difference of the
// two has an expected mean square of (noise of one + noise of the other + bias²). The noise part
// is measured from each pixel's own samples; the bias is the radiosity solution's discretisation
// (piecewise-constant elements read by the gather rays), bounded here by a stated allowance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "radiosity/render/image_renderer.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/render/radiosity_integrator.h"
#include "tests/render/render_fixture.h"

namespace rad {
namespace {

// Two independent renders per method: half the squared difference of the pair is an unbiased
// estimate of each render's noise variance, with no assumption about the samples' distribution.
struct PairedRender {
  ImageRgb mean, variance;  // of the average of the pair
};

PairedRender renderPair(const Camera& camera, const Integrator& integrator, int spp,
                        uint64_t seed) {
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.showProgress = false;
  settings.seed = seed;
  const RenderOutput a = renderImage(camera, integrator, settings);
  settings.seed = seed + 1000;
  const RenderOutput b = renderImage(camera, integrator, settings);
  PairedRender out{ImageRgb(camera.width, camera.height), ImageRgb(camera.width, camera.height)};
  for (size_t p = 0; p < a.image.pixels.size(); ++p) {
    const Rgb d = a.image.pixels[p] - b.image.pixels[p];
    out.mean.pixels[p] = 0.5 * (a.image.pixels[p] + b.image.pixels[p]);
    out.variance.pixels[p] = 0.25 * (d * d);  // Var(mean of 2) = Var(one)/2, E[d²] = 2 Var(one)
  }
  return out;
}

// The method's image against the path tracer's: relative RMSE within the two renders' noise plus
// `discretisation`, and each channel's image mean within 1%.
void expectAgreesWithPathTracer(const FinalGatherOptions& options, int spp, double discretisation) {
  SolveOptions solve;
  solve.targetElements = 3000;
  auto s = testing::solveForRender(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj",
                                   solve);
  Camera camera =
      loadCamera(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.camera.json");
  camera.width = camera.height = 64;

  const PairedRender path = renderPair(camera, PathTracer(*s->view), 128, 11);
  const PairedRender gather =
      renderPair(camera,
                 *makeRadiosityIntegrator(*s->view, s->solved.solution.radiosity,
                                          s->solved.solution.directIrradiance, options),
                 spp, 12);

  double diff2 = 0, ref2 = 0, noise2 = 0;
  Rgb meanPath, meanGather, varMeanPath, varMeanGather;
  const double n = path.mean.pixels.size();
  for (size_t p = 0; p < path.mean.pixels.size(); ++p) {
    const Rgb a = path.mean.pixels[p], b = gather.mean.pixels[p];
    const Rgb d = a - b;
    diff2 += (d * d).sum();
    ref2 += (a * a).sum();
    noise2 += (path.variance.pixels[p] + gather.variance.pixels[p]).sum();
    meanPath += a / n;
    meanGather += b / n;
    varMeanPath += path.variance.pixels[p] / (n * n);
    varMeanGather += gather.variance.pixels[p] / (n * n);
  }
  const double rmse = std::sqrt(diff2 / ref2), noiseRmse = std::sqrt(noise2 / ref2);
  std::printf("relative RMSE %.4f, expected from noise alone %.4f\n", rmse, noiseRmse);
  // E[diff²] = noise² + bias². The noise estimate is a sum over 12288 values (its relative
  // spread is about 1%), so 1.1 × noise² covers it; the radiosity solution's discretisation
  // error comes on top.
  EXPECT_LE(rmse, std::sqrt(1.1 * noiseRmse * noiseRmse + discretisation * discretisation));
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: mean path %.5f +- %.5f, gather %.5f +- %.5f, difference %.3f%%\n", c,
                meanPath[c], std::sqrt(varMeanPath[c]), meanGather[c], std::sqrt(varMeanGather[c]),
                100 * (meanGather[c] / meanPath[c] - 1));
    EXPECT_NEAR(meanGather[c] / meanPath[c], 1.0, 0.01) << "channel " << c;
  }
}

// The gather reads the solution's elements (3000) one bounce away: 3% relative RMSE allowed.
TEST(RenderCornell, FinalGatherAgreesWithPathTracer) { expectAgreesWithPathTracer({16}, 16, 0.03); }

// --gather 0 --light-rays 4: the direct light at each hit, the indirect part interpolated from
// the solution at the first hit, where its discretisation shows whole (the corners, the blocks'
// contacts): the same 3% (measured: 0.0230 against 0.0186 from noise alone, so about 1.4%).
TEST(RenderCornell, DirectLightWithTheSolutionsIndirectPartAgreesWithPathTracer) {
  expectAgreesWithPathTracer({0, 4}, 16, 0.03);
}

}  // namespace
}  // namespace rad
