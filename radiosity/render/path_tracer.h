#pragma once

#include "radiosity/render/path_integrator.h"

namespace rad {

struct PathTracerOptions {
  int rouletteAfter = 3;  // diffuse bounces before Russian roulette may end a path
};

// Unbiased reference: unidirectional path tracing with next-event estimation to the emitters
// and multiple importance sampling (power heuristic) against cosine-weighted bounces, Russian
// roulette on the path throughput, no clamping and no depth limit. Same scene, materials and
// BVH as the radiosity pass: one-sided Lambertian surfaces and emitters (a back face is black),
// mirrors reflecting Ks, dielectrics with Fresnel (Ni) and transmittance Tf.
// The point, spot, directional and sky lights are sampled at every diffuse vertex too (one
// shadow ray each, scene_lights.h); a bounce that leaves the scene sees the sky and the sun's
// disc, MIS-weighted against those samples, and a camera or specular ray sees them whole.
// Each contribution's label is the eye path's vertices (D or S) ending at the emitter: L(D|S)*E.
class PathTracer : public PathIntegrator {
 public:
  PathTracer(const RenderScene& scene, PathTracerOptions options = {});
  // Each bounce's light point, direction and roulette come from `sampler`, so the first bounces
  // are stratified across the pixel's samples as the final gather's are.
  Rgb trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
            RayCounts& counts, const PathBinning* binning, Rgb* binned,
            SplatImage* splats) const override;  // splats unused: all contributions are the pixel's
  std::string name() const override { return "path tracing"; }

 private:
  const RenderScene& scene_;
  PathTracerOptions options_;
};

}  // namespace rad
