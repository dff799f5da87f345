#pragma once

#include <Eigen/Core>
#include <string>

#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sampler.h"

namespace rad {

// Estimates the radiance (W·m⁻²·sr⁻¹) arriving at `origin` from `direction` (unit): one
// sample of a Monte Carlo estimator, or an exact lookup. Thread-safe; all randomness comes from
// `rng` (or `sampler`), so a pixel's stream alone fixes its value.
class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
                       RayCounts& counts) const = 0;
  // The same estimate with its random numbers drawn from `sampler`, which the image renderer
  // stratifies across a pixel's samples. Integrators that take dimensions from it override this;
  // the default draws everything from the sampler's free stream.
  virtual Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                       Sampler& sampler, RayCounts& counts) const {
    return radiance(origin, direction, sampler.rng(), counts);
  }
  virtual std::string name() const = 0;
};

// An integrator that draws every random number from a Sampler: its estimate from an Rng is the
// same estimate with the sampler's dimensions drawn from that Rng (RandomSampler).
class SamplerIntegrator : public Integrator {
 public:
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const final {
    RandomSampler sampler(rng);
    return radiance(origin, direction, sampler, counts);
  }
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override = 0;
};

}  // namespace rad
