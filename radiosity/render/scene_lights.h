#pragma once

#include <Eigen/Core>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/sampler.h"
#include "radiosity/scene/lights.h"

namespace rad {

class RenderScene;
struct SurfaceHit;
struct RayCounts;

// The scene's point, spot, directional, sky and environment lights (scene/lights.h) as the camera
// renders see them, next to the emissive polygons of EmitterSampler. Two kinds:
//  - delta lights (point, spot, a hard sun): one direction each, which no scattered ray can hit;
//    next-event estimation alone sees them, exactly, with one shadow ray each;
//  - area lights at infinity (a sun with an angular diameter, the sky, the environment):
//    next-event estimation draws one direction per light (uniform over the sun's disc, density
//    1/Ω; by the map's luminance for the environment and the CIE clear sky, density
//    EnvironmentMap::pdf; cosine-weighted about the surface normal for the other skies, density
//    cosθ/π), and a cosine-sampled ray that leaves the scene sees them too; the two are weighed by
//    multiple importance sampling (power heuristic, counting the rays of each kind), so both stay
//    unbiased and neither is noisy.
// Rays that leave the scene see the sky above its horizon (black ground below), the environment
// all round and the sun's disc of radiance E / (π sin²h) (light_shapes.h): camera rays too, so
// the background shows them.
class SceneLights {
 public:
  explicit SceneLights(const std::vector<Light>& lights);
  bool empty() const { return lights_.empty(); }

  // One delta light's light at a surface point, after its shadow ray.
  struct Arrival {
    Eigen::Vector3d direction;  // unit, towards the light
    Rgb irradiance;             // on the surface: E⊥ cosθ (W/m²)
  };
  // The unshadowed delta lights at `hit` (front side, cosθ > 0), appended to `out` (cleared).
  void deltaArrivals(const RenderScene& scene, const SurfaceHit& hit, RayCounts& counts,
                     double time, std::vector<Arrival>& out) const;
  // Their sum: the irradiance at `hit` from the delta lights (W/m²), exact.
  Rgb deltaIrradiance(const RenderScene& scene, const SurfaceHit& hit, RayCounts& counts,
                      double time = 0) const;

  // Area lights at infinity: how many, and one next-event sample of the k-th from `u`: an
  // estimate of its irradiance at `hit` (W/m²), MIS-weighted against `bsdfPerLight` cosine rays
  // per light sample (0: no such rays, weight 1).
  int areaCount() const { return static_cast<int>(areaLights_.size()); }
  int deltaCount() const { return static_cast<int>(deltaLights_.size()); }
  Rgb sampleArea(int k, const RenderScene& scene, const SurfaceHit& hit, Point2 u,
                 RayCounts& counts, double bsdfPerLight, double time = 0) const;
  // All lights at `hit`: the delta lights plus one sample of each area light (a 2D point each
  // from `sampler`): an estimate of the irradiance (W/m²).
  Rgb sampleIrradiance(const RenderScene& scene, const SurfaceHit& hit, Sampler& sampler,
                       RayCounts& counts, double bsdfPerLight, double time = 0) const;

  // Radiance along a ray that leaves the scene in the unit `direction`, all of it: for camera
  // rays, rays after a mirror or glass, and methods that do not sample the area lights.
  Rgb escapedRadiance(const Eigen::Vector3d& direction) const;
  // The share of a cosine-sampled ray from a surface of unit normal `normal` that the area lights'
  // next-event samples did not take: each light's radiance times its MIS weight.
  Rgb escapedRadiance(const Eigen::Vector3d& direction, const Eigen::Vector3d& normal,
                      double bsdfPerLight) const;

  // The irradiance at a point with unit normal `n` from every light, ignoring shadows (the local
  // model of `direct`): the hard sun at the disc's centre, the sky in closed form.
  Rgb unshadowedIrradiance(const Eigen::Vector3d& x, const Eigen::Vector3d& n) const;

 private:
  std::vector<Light> lights_;
  std::vector<int> deltaLights_, areaLights_;  // indices into lights_
};

}  // namespace rad
