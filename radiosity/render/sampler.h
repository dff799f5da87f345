#pragma once

#include <vector>

#include "radiosity/core/rng.h"
#include "radiosity/render/stratified.h"

namespace rad {

struct Point2 {
  double x = 0, y = 0;
};

// Where an integrator takes its random numbers from, one dimension (or pair) at a time, so the
// image renderer can hand it points that are stratified across a pixel's samples. Every point is
// uniform on its own, so any sampler keeps an estimator unbiased; better ones only lower noise.
class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual double get1D() = 0;
  virtual Point2 get2D() = 0;
  // `count` points of one 2D dimension for this sample (N shadow or gather rays at one hit),
  // stratified among themselves.
  virtual void get2DArray(int count, std::vector<Point2>& out) = 0;
  // Free randomness (choices that need no stratification), from the pixel's own stream.
  virtual Rng& rng() = 0;
};

// Independent random numbers from one stream; arrays are n-rooks stratified.
class RandomSampler : public Sampler {
 public:
  explicit RandomSampler(Rng& rng) : rng_(rng) {}
  double get1D() override { return rng_.uniform(); }
  Point2 get2D() override {
    const double x = rng_.uniform();
    return {x, rng_.uniform()};
  }
  void get2DArray(int count, std::vector<Point2>& out) override {
    thread_local std::vector<std::pair<double, double>> strata;
    nRooks(count, rng_, strata);
    out.resize(count);
    for (int k = 0; k < count; ++k) out[k] = {strata[k].first, strata[k].second};
  }
  Rng& rng() override { return rng_; }

 private:
  Rng& rng_;
};

}  // namespace rad
