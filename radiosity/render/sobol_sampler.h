#pragma once

#include <cstdint>

#include "radiosity/render/sampler.h"

namespace rad {

// Owen-scrambled Sobol points, "padded" (pbrt-v4's PaddedSobolSampler; Burley 2020, "Practical
// Hash-based Owen Scrambling"): every 2D dimension of a pixel is the first two Sobol dimensions,
// a (0,2)-sequence, with its own nested scramble of the index and of both coordinates, keyed by
// (seed, pixel, dimension). So the pixel's samples are stratified in each 2D dimension on its
// own: for a power-of-two count every elementary interval (1×n, 2×n/2, …, n×1) holds exactly one
// point, and a discontinuity (an object's edge, a shadow's edge) costs O(n^-1.5) variance instead
// of the O(n^-1) of independent points. Dimensions are paired at random with each other, as in
// independent sampling. Each point is uniform on [0,1)², so estimators stay unbiased.
class SobolSampler : public Sampler {
 public:
  // `rng` serves rng() (the pixel's own stream).
  SobolSampler(uint64_t seed, uint64_t pixel, Rng& rng);
  // Starts the pixel's sample `index` (0, 1, 2, …) at its first dimension.
  void startSample(int index);

  double get1D() override { return get2D().x; }
  Point2 get2D() override;
  // Points `sample·count + k` of the dimension's sequence: the N-ray arrays of all the pixel's
  // samples form one stratified set.
  void get2DArray(int count, std::vector<Point2>& out) override;
  Rng& rng() override { return rng_; }

  // The Owen-scrambled Sobol point `index` of the (0,2)-sequence scrambled by `key`.
  static Point2 point(uint32_t index, uint64_t key);

 private:
  uint64_t pixelKey_;
  int sample_ = 0;
  uint32_t dimension_ = 0;
  Rng& rng_;
};

}  // namespace rad
