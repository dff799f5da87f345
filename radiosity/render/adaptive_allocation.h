#pragma once

#include <cstdint>
#include <vector>

namespace rad {

// Adaptive pixel sampling (`render --adaptive`): how many samples each pixel gets after a first
// pass of `base` samples in every pixel, so that the pixels whose light varies most (a light's
// outline, a shadow's edge, a noisy gather) get most of them.
//
// Each pixel's share is proportional to its guide, the largest standard deviation per sample
// among its (up to 8) neighbours in the first pass: for a fixed number of samples the sum of the
// pixels' squared errors, Σ σᵢ²/nᵢ, is least for nᵢ ∝ σᵢ. The neighbours' spread is used and not
// the pixel's own, and the shares are normalised by the guides' sum taken as if the pixel had no
// spread, so a pixel's count never depends on its own samples and its mean stays unbiased (every
// Owen-scrambled Sobol point is uniform, whatever the count). A thin feature (an outline one
// pixel wide) is its own neighbour along its length, so it is still found; its neighbours across
// get as many samples.
struct AdaptiveAllocation {
  std::vector<int> extra;  // per pixel (row-major), samples after the first pass
  int64_t total = 0;       // Σ extra
};

// `sigma`: per pixel, the standard deviation of one sample (from the first pass). `budget`: the
// samples to share out; no pixel gets more than `maxPerPixel`. A budget left over by that cap or
// by rounding is not spent elsewhere, and the leave-one-out sums make the total differ from
// `budget` by a little (the share of a pixel's own spread in the sum). With every guide 0 (a
// uniform image, or no spread seen) the budget is shared evenly.
AdaptiveAllocation allocateAdaptiveSamples(const std::vector<double>& sigma, int width, int height,
                                           int64_t budget, int maxPerPixel);

}  // namespace rad
