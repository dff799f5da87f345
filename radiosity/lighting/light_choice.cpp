#include "radiosity/lighting/light_choice.h"

#include "radiosity/core/check.h"

namespace rad {

LightChoice chooseLight(const std::vector<const Light*>& lights, const Eigen::Vector3d& x,
                        const Eigen::Vector3d& n, double u) {
  thread_local std::vector<LightSample> samples;
  samples.clear();
  double total = 0;
  for (const Light* light : lights) {
    RAD_CHECK_MSG(isDeltaLight(*light), "chooseLight takes delta lights");
    samples.push_back(sampleLight(*light, x, n, 0, 0));
    total += samples.back().irradiance.luminance();
  }
  LightChoice choice;
  if (!(total > 0)) return choice;
  double pick = u * total;
  for (size_t l = 0; l < lights.size(); ++l) {
    const double share = samples[l].irradiance.luminance();
    if (share <= 0) continue;
    choice.index = l;  // the last one with a share, should rounding leave `pick` just above 0
    pick -= share;
    if (pick < 0) break;
  }
  choice.sample = samples[choice.index];
  choice.weight = total / choice.sample.irradiance.luminance();
  return choice;
}

}  // namespace rad
