#pragma once

#include <cstdint>
#include <string>

#include "radiosity/core/image.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/integrator.h"

namespace rad {

struct RenderSettings {
  // Owen-scrambled Sobol points (SobolSampler) stratify the pixel, the lens and every dimension
  // an integrator draws through its Sampler across the pixel's samples.
  int samplesPerPixel = 4;
  uint64_t seed = 1;
  bool showProgress = true;
};

struct RenderOutput {
  ImageRgb image;  // mean radiance per pixel, W·m⁻²·sr⁻¹
  // Estimated variance of each pixel's mean: the sample variance of its samples / n (0 when
  // n = 1), as for independent samples. Stratification usually makes the true variance smaller
  // (scrambled nets can exceed it at most by a small constant factor, Owen 1997).
  ImageRgb variance;
  RayCounts rays;
  double seconds = 0;
};

// Stores pixel (x, y)'s mean from n samples' sum and sum of squares, and the variance of that mean
// (0 when n = 1).
void storePixelMean(RenderOutput& out, int x, int y, const Rgb& sum, const Rgb& sumSquares, int n);

// Renders every pixel with `integrator`. Pixel (x, y) draws from its own random stream keyed by
// (seed, y·width + x), so the image is the same on any thread count.
RenderOutput renderImage(const Camera& camera, const Integrator& integrator,
                         const RenderSettings& settings);

}  // namespace rad
