#pragma once

#include <algorithm>

#include "radiosity/core/rgb.h"

namespace rad {

// A specular chain longer than this plays Russian roulette at every further step, so glass with
// total internal reflection cannot trap a path forever and no fixed cut-off biases the result (a
// glass panel seen edge-on guides a ray along itself for dozens of reflections: a cut-off at 16
// left such edges black). The path tracer, BDPT, the final gather and the extended form factors
// all start their roulette here.
constexpr int kSpecularRouletteAfter = 8;

// Russian roulette with `u` uniform in [0, 1): the path goes on with probability
// min(0.95, max throughput), its throughput divided by that probability. The path tracer and BDPT
// use it. A chain through glass loses no weight (Fresnel picks reflection or refraction), so this
// roulette raises its weight by 1/0.95 a step: where internal reflections are likely (a glass
// sphere entered at grazing incidence), the weights' variance grows without bound. The final
// gather, whose gather rays meet such chains far more often, uses the variant below.
inline bool survivesRoulette(Rgb& throughput, double u) {
  const double q = std::min(0.95, throughput.maxComponent());
  if (u >= q) return false;
  throughput *= 1.0 / q;
  return true;
}

// The final gather's and the form-factor rows' variant: the path goes on with probability
// min(1, max throughput), so a weight never rises above its largest value before the roulette
// (every row keeps sum_j F_ij <= 1 ray by ray, tests/stress/test_row_conservation.cpp; no firefly
// grows in the gather). A chain that loses nothing (glass of Tf 1, mirrors of Ks 1) is never ended
// by it; kSpecularBounceLimit ends one trapped for good.
inline bool survivesRouletteWithinOne(Rgb& throughput, double u) {
  const double q = std::min(1.0, throughput.maxComponent());
  if (u >= q) return false;
  throughput *= 1.0 / q;
  return true;
}

// Specular bounces after which a gather or form-factor ray is given up: far beyond any light guide
// of a real scene (a 4 m glass panel 4 cm thick takes a few hundred), it only bounds the work of a
// ray that could bounce forever between lossless surfaces.
constexpr int kSpecularBounceLimit = 1024;

}  // namespace rad
