#pragma once

#include <vector>

#include "radiosity/render/integrator.h"
#include "radiosity/render/point_lights.h"

namespace rad {

// The OpenGL local model, `LDE` (and `LE` where an emitter is seen): the closest surface along
// the eye ray, lit by every emitter shrunk to a point light at its centre (point_lights.h),
// with no shadows and no light from other surfaces; the point, spot, directional and sky lights
// likewise unshadowed (the sun as a hard sun, the sky as the closed form πL(1 + n·up)/2, rays
// that miss the scene see the sky). Every surface is shaded as Lambertian with
// its Kd: L = Le + Kd/π · Σ_lights E. Mirrors and glass show their Kd (black for the usual
// Kd 0), since the local model has no reflected or refracted view. Back faces are black, as in
// every other method. Deterministic: draws no random numbers.
class DirectLighting : public Integrator {
 public:
  explicit DirectLighting(const RenderScene& scene);
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override;
  std::string name() const override { return "direct (local model)"; }

 private:
  const RenderScene& scene_;
  std::vector<PointLight> lights_;
};

}  // namespace rad
