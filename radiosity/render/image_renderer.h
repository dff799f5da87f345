#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radiosity/core/image.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/integrator.h"

namespace rad {

struct RenderSettings {
  // Owen-scrambled Sobol points (SobolSampler) stratify the pixel, the lens and every dimension
  // an integrator draws through its Sampler across the pixel's samples.
  int samplesPerPixel = 4;
  // Adaptive pixel sampling (adaptive_allocation.h): samplesPerPixel is then the mean over the
  // image; a quarter of it goes to every pixel first, the rest where the neighbours' samples
  // spread most. Below kMinAdaptiveSpp it samples uniformly (no spread to measure).
  bool adaptive = false;
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
  // Per pixel (row-major), the samples taken: filled by an adaptive render, empty otherwise.
  std::vector<int> samples;
};

// The fewest samples per pixel an adaptive render shares out: its first pass (a quarter) must
// have two samples for a spread.
constexpr int kMinAdaptiveSpp = 8;
// No pixel of an adaptive render takes more than this many times the mean.
constexpr int kMaxAdaptiveFactor = 64;

// Stores pixel (x, y)'s mean from n samples' sum and sum of squares, and the variance of that mean
// (0 when n = 1).
void storePixelMean(RenderOutput& out, int x, int y, const Rgb& sum, const Rgb& sumSquares, int n);

// Renders every pixel with `integrator`. Pixel (x, y) draws from its own random stream keyed by
// (seed, y·width + x), so the image is the same on any thread count; so is an adaptive render's
// allocation, which depends only on the first pass.
RenderOutput renderImage(const Camera& camera, const Integrator& integrator,
                         const RenderSettings& settings);

}  // namespace rad
