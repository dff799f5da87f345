#pragma once

#include <string>

#include "radiosity/render/integrator.h"
#include "radiosity/render/path_binning.h"
#include "radiosity/render/splat_image.h"

namespace rad {

// An integrator that sums contributions of whole light paths, each with a known Heckbert label:
// it can sort them into images by path type (--paths, --bounces-separate). The random numbers
// drawn do not depend on the binning, so the binned images of a partition sum exactly (up to
// float rounding) to the unbinned one.
class PathIntegrator : public Integrator {
 public:
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override {
    RandomSampler sampler(rng);
    return trace(origin, direction, sampler, counts, nullptr, nullptr, nullptr);
  }
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override {
    return trace(origin, direction, sampler, counts, nullptr, nullptr, nullptr);
  }
  // Returns the sum of the contributions to this camera sample's pixel; with `binning`, also
  // adds each one to binned[binning->binOf(label)] (binned has binning->binCount() entries).
  // With `splats`, an integrator may also add contributions to other pixels there (in units
  // the renderer divides by the samples per pixel); without, it must not use such strategies.
  virtual Rgb trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                    Sampler& sampler, RayCounts& counts, const PathBinning* binning, Rgb* binned,
                    SplatImage* splats) const = 0;
};

// Appends the eye-side vertex labels (collected eye to light, e.g. "DS" for the first hit D then
// S) reversed, between the emitter's L and the eye's E: the light-to-eye label ("LSDE").
inline void lightToEyeLabel(std::string& label, std::string_view lightSide,
                            std::string_view eyeSide) {
  label.assign("L");
  label.append(lightSide);
  label.append(eyeSide.rbegin(), eyeSide.rend());
  label.push_back('E');
}

}  // namespace rad
