#include "radiosity/render/image_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <memory>

#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"
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

RenderOutput renderImage(const Camera& camera, const Integrator& integrator,
                         const RenderSettings& settings) {
  RAD_CHECK_GE(settings.samplesPerPixel, 1);  // the commands refuse --spp below 1
  const auto start = std::chrono::steady_clock::now();
  const CameraRays rays(camera);
  RenderOutput out;
  out.image = ImageRgb(camera.width, camera.height);
  out.variance = ImageRgb(camera.width, camera.height);
  const int n = settings.samplesPerPixel;
  std::unique_ptr<Progress> progress;
  if (settings.showProgress)
    progress = std::make_unique<Progress>("render (" + integrator.name() + ")",
                                          static_cast<uint64_t>(camera.height), "rows");
  tbb::combinable<RayCounts> counts;

  tbb::parallel_for(
      tbb::blocked_range<int>(0, camera.height), [&](const tbb::blocked_range<int>& r) {
        RayCounts& local = counts.local();
        for (int y = r.begin(); y < r.end(); ++y) {
          for (int x = 0; x < camera.width; ++x) {
            const uint64_t pixel = static_cast<uint64_t>(y) * camera.width + x;
            Rng rng(streamKey(settings.seed, pixel, 0x52454e44));
            SobolSampler sampler(settings.seed, pixel, rng);
            Rgb sum, sumSquares;
            for (int s = 0; s < n; ++s) {
              sampler.startSample(s);
              const Point2 film = sampler.get2D(), lens = sampler.get2D();
              Eigen::Vector3d origin, direction;
              rays.generate(x + film.x, y + film.y, lens.x, lens.y, origin, direction);
              const Rgb L = integrator.radiance(origin, direction, sampler, local);
              sum += L;
              sumSquares += L * L;
            }
            storePixelMean(out, x, y, sum, sumSquares, n);
          }
          if (progress) progress->advance();
        }
      });
  out.rays = counts.combine([](RayCounts a, const RayCounts& b) { return a += b; });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress) progress->finish(std::to_string(out.rays.total()) + " rays");
  return out;
}

}  // namespace rad
