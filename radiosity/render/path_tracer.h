#pragma once

#include "radiosity/render/integrator.h"

namespace rad {

struct PathTracerOptions {
  int rouletteAfter = 3;  // diffuse bounces before Russian roulette may end a path
};

// Unbiased reference: unidirectional path tracing with next-event estimation to the emitters
// and multiple importance sampling (power heuristic) against cosine-weighted bounces, Russian
// roulette on the path throughput, no clamping and no depth limit. Same scene, materials and
// BVH as the radiosity pass: one-sided Lambertian surfaces and emitters (a back face is black),
// mirrors reflecting Ks, dielectrics with Fresnel (Ni) and transmittance Tf.
class PathTracer : public Integrator {
 public:
  PathTracer(const RenderScene& scene, PathTracerOptions options = {});
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override;
  // Each bounce's light point, direction and roulette come from `sampler`, so the first bounces
  // are stratified across the pixel's samples as the final gather's are.
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override;
  std::string name() const override { return "path tracing"; }

 private:
  const RenderScene& scene_;
  PathTracerOptions options_;
};

}  // namespace rad
