#include "radiosity/render/path_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <memory>

#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/render/sobol_sampler.h"

namespace rad {
namespace {

void addSplats(RenderOutput& out, const ImageRgb& sum, const ImageRgb& sumSquares, int spp,
               double paths) {
  for (size_t p = 0; p < out.image.pixels.size(); ++p) {
    const Rgb v = sum.pixels[p] / spp, v2 = sumSquares.pixels[p] / (static_cast<double>(spp) * spp);
    out.image.pixels[p] += v;
    Rgb var = v2 - v * v / paths;
    for (int c = 0; c < 3; ++c) var[c] = std::max(0.0, var[c]);
    out.variance.pixels[p] += var;
  }
}

}  // namespace

PathRenderOutput renderPathImage(const Camera& camera, const PathIntegrator& integrator,
                                 const RenderSettings& settings, const PathBinning* binning) {
  RAD_CHECK_GE(settings.samplesPerPixel, 1);  // the commands refuse --spp below 1
  const auto start = std::chrono::steady_clock::now();
  const CameraRays rays(camera);
  const int n = settings.samplesPerPixel, bins = binning ? binning->binCount() : 0;
  const int width = camera.width, height = camera.height;
  PathRenderOutput out;
  out.full.image = out.full.variance = ImageRgb(width, height);
  out.bins.resize(bins);
  for (RenderOutput& b : out.bins) b.image = b.variance = ImageRgb(width, height);
  std::unique_ptr<Progress> progress;
  if (settings.showProgress)
    progress = std::make_unique<Progress>("render (" + integrator.name() + ")",
                                          static_cast<uint64_t>(height), "rows");
  struct ThreadState {
    RayCounts counts;
    std::unique_ptr<SplatImage> splats;
  };
  tbb::enumerable_thread_specific<ThreadState> threads;

  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& r) {
    ThreadState& local = threads.local();
    if (!local.splats) local.splats = std::make_unique<SplatImage>(width, height, bins);
    std::vector<Rgb> binned(bins), binSum(bins), binSumSquares(bins);
    for (int y = r.begin(); y < r.end(); ++y) {
      for (int x = 0; x < width; ++x) {
        // The stream key and the draws are renderImage's: same seed, same samples.
        const uint64_t pixel = static_cast<uint64_t>(y) * width + x;
        Rng rng(streamKey(settings.seed, pixel, stream_tag::kPixel));
        SobolSampler sampler(settings.seed, pixel, rng);
        Rgb sum, sumSquares;
        std::fill(binSum.begin(), binSum.end(), Rgb());
        std::fill(binSumSquares.begin(), binSumSquares.end(), Rgb());
        for (int s = 0; s < n; ++s) {
          sampler.startSample(s);
          const Point2 film = sampler.get2D(), lens = sampler.get2D();
          Eigen::Vector3d origin, direction;
          rays.generate(x + film.x, y + film.y, lens.x, lens.y, origin, direction);
          std::fill(binned.begin(), binned.end(), Rgb());
          const Rgb L = integrator.trace(origin, direction, sampler, local.counts, binning,
                                         binned.data(), local.splats.get());
          sum += L;
          sumSquares += L * L;
          for (int b = 0; b < bins; ++b) {
            binSum[b] += binned[b];
            binSumSquares[b] += binned[b] * binned[b];
          }
        }
        storePixelMean(out.full, x, y, sum, sumSquares, n);
        for (int b = 0; b < bins; ++b)
          storePixelMean(out.bins[b], x, y, binSum[b], binSumSquares[b], n);
      }
      if (progress) progress->advance();
    }
  });

  // Light-tracing splats, summed over the threads.
  const double paths = static_cast<double>(width) * height * n;
  SplatImage splats(width, height, bins);
  for (ThreadState& t : threads) {
    out.full.rays += t.counts;
    if (!t.splats) continue;
    for (size_t p = 0; p < splats.sum.pixels.size(); ++p) {
      splats.sum.pixels[p] += t.splats->sum.pixels[p];
      splats.sumSquares.pixels[p] += t.splats->sumSquares.pixels[p];
      for (int b = 0; b < bins; ++b) {
        splats.binSum[b].pixels[p] += t.splats->binSum[b].pixels[p];
        splats.binSumSquares[b].pixels[p] += t.splats->binSumSquares[b].pixels[p];
      }
    }
  }
  addSplats(out.full, splats.sum, splats.sumSquares, n, paths);
  for (int b = 0; b < bins; ++b)
    addSplats(out.bins[b], splats.binSum[b], splats.binSumSquares[b], n, paths);
  out.full.seconds = secondsSince(start);
  if (progress) progress->finish(std::to_string(out.full.rays.total()) + " rays");
  return out;
}

}  // namespace rad
