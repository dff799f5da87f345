#pragma once

#include <vector>

#include "radiosity/render/integrator.h"
#include "radiosity/render/point_lights.h"

namespace rad {

struct WhittedOptions {
  int maxDepth = 8;         // mirror/glass interactions along one branch
  double minWeight = 1e-3;  // branches whose throughput falls below this are not traced
};

// Whitted (1980) ray tracing, `LD?S*E`: at a diffuse surface, Kd/π times the light of every
// emitter shrunk to a point light at its centre (point_lights.h), each behind one shadow ray
// (glass casts a shadow like any surface); mirrors reflect Ks times the mirrored view;
// glass splits deterministically into Fresnel reflection (weight F) and refraction (weight
// (1−F)·Tf·(η_i/η_t)²), both traced recursively, up to maxDepth specular interactions.
// The point, spot and hard directional lights light a diffuse surface exactly, each behind one
// shadow ray; the sun's disc and the sky by one sampled direction each (the only random numbers
// drawn, so a scene without them renders deterministically); rays that leave the scene see the
// sky (scene_lights.h). No diffuse interreflection.
class WhittedRayTracer : public Integrator {
 public:
  explicit WhittedRayTracer(const RenderScene& scene, WhittedOptions options = {});
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override;
  std::string name() const override { return "Whitted ray tracing"; }

 private:
  Rgb trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, int depth,
            double weight, Rng& rng, RayCounts& counts) const;
  const RenderScene& scene_;
  WhittedOptions options_;
  std::vector<PointLight> lights_;
};

}  // namespace rad
