#pragma once

#include <cstddef>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// The power of an emitting element, the weight by which every estimator picks emitters: its area
// times its emission summed over the channels (Ke or E = πKe alike: only the proportions count).
// The sum, not the luminance: an image's error is every channel's, and weighing by luminance left
// a red or blue lamp's light to few samples (the staircase's split at 16 spp: 14% more error).
// The solve's emitter first shot (pipeline/emitter_first_shot) and the renders' emitter samples
// (render/emitter_sampler) both pick by it.
// Per unit area (the power of a unit of the emitter's area): what a density over the emitters'
// area is proportional to.
inline double emitterPowerPerArea(const Rgb& emission) { return emission.sum(); }
inline double emitterPower(double area, const Rgb& emission) {
  return area * emitterPowerPerArea(emission);
}

// A choice among n items in proportion to their weights (powers), by one number u in [0, 1):
// bright, large emitters get the samples. The items keep the order they are given in, so a
// caller that orders them in space (the solve: Morton order) keeps stratified u stratified in
// space too.
class PowerDistribution {
 public:
  PowerDistribution() = default;
  // Weights ≥ 0; those of weight 0 are never picked.
  explicit PowerDistribution(const std::vector<double>& weights);
  bool empty() const { return cumulative_.empty(); }
  size_t size() const { return cumulative_.size(); }
  double total() const { return total_; }  // the weights' sum

  size_t pick(double u) const;  // the item whose share of [0, 1) holds u
  double probability(size_t k) const { return probability_[k]; }
  // u rescaled to [0, 1) within the share of the item it picks (`pick(u)`), to go on sampling a
  // point of that item with it: a stratified u stays stratified over the items' whole extent.
  double rescaled(double u, size_t k) const;

 private:
  std::vector<double> cumulative_;   // the weights summed, normalised to end at 1
  std::vector<double> probability_;  // each one's share
  double total_ = 0;
};

}  // namespace rad
