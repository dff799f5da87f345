#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "radiosity/lighting/light_sample.h"

namespace rad {

// Up to this many point and spot lights, every one gets a shadow ray from each lit point; with
// more, each point casts one, to a light chosen by chooseLight, so a scene with hundreds of lamps
// costs no more per point (the solve's first shot, the renders' next-event estimation).
constexpr size_t kEveryPointLight = 4;

// One of many point and spot lights for a point's shadow ray, with the weight that keeps the
// estimate of their sum unbiased.
struct LightChoice {
  size_t index = 0;    // into the lights given
  LightSample sample;  // its sample at the point (not found: no light lights the point)
  double weight = 0;   // 1 / the probability of this choice
};

// Every light's unshadowed irradiance at (x, n) is cheap (no ray): the light is chosen in
// proportion to its luminance there, by `u` in [0, 1), which is the power each light sends the
// point, and better than its power alone (a bright lamp across the building gets no rays here).
// sample.irradiance × weight is unbiased for the lights' sum, and exact wherever all the lights
// see x alike. The lights must be delta lights (RAD_CHECK).
LightChoice chooseLight(const std::vector<const Light*>& lights, const Eigen::Vector3d& x,
                        const Eigen::Vector3d& n, double u);

}  // namespace rad
