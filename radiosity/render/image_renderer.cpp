#include "radiosity/render/image_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/render/adaptive_allocation.h"
#include "radiosity/render/sobol_sampler.h"

namespace rad {

void storePixelMean(RenderOutput& out, int x, int y, const Rgb& sum, const Rgb& sumSquares, int n) {
  const Rgb mean = sum / n;
  out.image.at(x, y) = mean;
  if (n > 1) {
    Rgb var = (sumSquares - mean * sum) / (static_cast<double>(n) * (n - 1));
    for (int c = 0; c < 3; ++c) var[c] = std::max(0.0, var[c]);
    out.variance.at(x, y) = var;
  }
}

namespace {

// The first pass's per-pixel sums, and then the second's added to them.
struct PixelSums {
  std::vector<Rgb> sum, squares;
  std::vector<int> count;
};

// Runs `row(y, local)` over every row in parallel, with the progress advanced per row.
template <typename RowFn>
void forEachRow(int height, Progress* progress, tbb::combinable<RayCounts>& counts, RowFn row) {
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& r) {
    RayCounts& local = counts.local();
    for (int y = r.begin(); y < r.end(); ++y) {
      row(y, local);
      if (progress) progress->advance();
    }
  });
}

// The standard deviation of one sample of a pixel (the channels' variances summed, as the plain
// RMSE sums them), from n ≥ 2 samples.
double sampleSpread(const Rgb& sum, const Rgb& squares, int n) {
  double v = 0;
  for (int c = 0; c < 3; ++c) v += std::max(0.0, squares[c] - sum[c] * sum[c] / n) / (n - 1);
  return std::sqrt(v);
}

}  // namespace

RenderOutput renderImage(const Camera& camera, const Integrator& integrator,
                         const RenderSettings& settings) {
  RAD_CHECK_GE(settings.samplesPerPixel, 1);  // the commands refuse --spp below 1
  const auto start = std::chrono::steady_clock::now();
  const CameraRays rays(camera);
  RenderOutput out;
  out.image = ImageRgb(camera.width, camera.height);
  out.variance = ImageRgb(camera.width, camera.height);
  const int n = settings.samplesPerPixel;
  const bool adaptive = settings.adaptive && n >= kMinAdaptiveSpp;
  const int firstPass = adaptive ? n / 4 : n;
  std::unique_ptr<Progress> progress;
  if (settings.showProgress)
    progress = std::make_unique<Progress>("render (" + integrator.name() + ")",
                                          static_cast<uint64_t>(camera.height) * (adaptive ? 2 : 1),
                                          "rows");
  tbb::combinable<RayCounts> counts;
  const size_t pixels = static_cast<size_t>(camera.width) * camera.height;
  PixelSums sums{std::vector<Rgb>(pixels), std::vector<Rgb>(pixels), std::vector<int>(pixels)};

  // Samples [from, to) of pixel (x, y). The second pass draws its free randomness from another
  // stream than the first's, so its samples are independent of the first's.
  auto samplePixel = [&](int x, int y, int from, int to, uint64_t stream, RayCounts& local) {
    const uint64_t pixel = static_cast<uint64_t>(y) * camera.width + x;
    Rng rng(streamKey(settings.seed, pixel, stream));
    SobolSampler sampler(settings.seed, pixel, rng);
    Rgb& sum = sums.sum[pixel];
    Rgb& squares = sums.squares[pixel];
    for (int s = from; s < to; ++s) {
      sampler.startSample(s);
      const Point2 film = sampler.get2D(), lens = sampler.get2D();
      Eigen::Vector3d origin, direction;
      rays.generate(x + film.x, y + film.y, lens.x, lens.y, origin, direction);
      const Rgb L = integrator.radiance(origin, direction, sampler, local);
      sum += L;
      squares += L * L;
    }
    sums.count[pixel] = to;
  };
  forEachRow(camera.height, progress.get(), counts, [&](int y, RayCounts& local) {
    for (int x = 0; x < camera.width; ++x)
      samplePixel(x, y, 0, firstPass, stream_tag::kPixel, local);
  });
  if (adaptive) {
    std::vector<double> spread(pixels);
    for (size_t p = 0; p < pixels; ++p)
      spread[p] = sampleSpread(sums.sum[p], sums.squares[p], firstPass);
    const AdaptiveAllocation extra =
        allocateAdaptiveSamples(spread, camera.width, camera.height,
                                static_cast<int64_t>(n - firstPass) * static_cast<int64_t>(pixels),
                                kMaxAdaptiveFactor * n - firstPass);
    forEachRow(camera.height, progress.get(), counts, [&](int y, RayCounts& local) {
      for (int x = 0; x < camera.width; ++x) {
        const size_t p = static_cast<size_t>(y) * camera.width + x;
        samplePixel(x, y, firstPass, firstPass + extra.extra[p], stream_tag::kAdaptivePass, local);
      }
    });
    out.samples = sums.count;
  }
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const size_t p = static_cast<size_t>(y) * camera.width + x;
      storePixelMean(out, x, y, sums.sum[p], sums.squares[p], sums.count[p]);
    }
  out.rays = counts.combine([](RayCounts a, const RayCounts& b) { return a += b; });
  out.seconds = secondsSince(start);
  if (progress) progress->finish(std::to_string(out.rays.total()) + " rays");
  return out;
}

}  // namespace rad
