#pragma once

#include <cstdint>
#include <string>

#include "radiosity/core/image.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/integrator.h"

namespace rad {

struct RenderSettings {
  int samplesPerPixel = 4;  // stratified over the pixel (and the lens) by n-rooks
  uint64_t seed = 1;
  bool showProgress = true;
};

struct RenderOutput {
  ImageRgb image;  // mean radiance per pixel, W·m⁻²·sr⁻¹
  // Estimated variance of each pixel's mean: the sample variance of its samples / n (0 when
  // n = 1). Stratification makes it an over-estimate, so tolerances built on it are safe.
  ImageRgb variance;
  RayCounts rays;
  double seconds = 0;
};

// Renders every pixel with `integrator`. Pixel (x, y) draws from its own random stream keyed by
// (seed, y·width + x), so the image is the same on any thread count.
RenderOutput renderImage(const Camera& camera, const Integrator& integrator,
                         const RenderSettings& settings);

}  // namespace rad
