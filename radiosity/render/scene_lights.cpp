#include "radiosity/render/scene_lights.h"

#include <algorithm>
#include <cmath>

#include "radiosity/lighting/light_sample.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/scattering.h"

namespace rad {
namespace {

// Power heuristic for one strategy of density `a` against another of density `b` (each already
// multiplied by its count of rays).
double powerHeuristic(double a, double b) { return a > 0 ? a * a / (a * a + b * b) : 0.0; }

}  // namespace

SceneLights::SceneLights(const std::vector<Light>& lights) : lights_(lights) {
  for (size_t k = 0; k < lights_.size(); ++k)
    (isDeltaLight(lights_[k]) ? deltaLights_ : areaLights_).push_back(static_cast<int>(k));
}

void SceneLights::deltaArrivals(const RenderScene& scene, const SurfaceHit& hit, RayCounts& counts,
                                double time, std::vector<Arrival>& out) const {
  out.clear();
  for (const int k : deltaLights_) {
    const LightSample s = sampleLight(lights_[k], hit.position, hit.normal, 0, 0);
    if (!s.found()) continue;
    ++counts.shadow;
    const Eigen::Vector3d origin = scene.spawn(hit, s.direction);
    if (std::isfinite(s.distance)
            ? scene.occluded(origin, hit.position + s.direction * s.distance, time)
            : scene.occludedAlong(origin, s.direction, time))
      continue;
    out.push_back({s.direction, s.irradiance});
  }
}

Rgb SceneLights::deltaIrradiance(const RenderScene& scene, const SurfaceHit& hit, RayCounts& counts,
                                 double time) const {
  if (deltaLights_.empty()) return {};
  thread_local std::vector<Arrival> arrivals;
  deltaArrivals(scene, hit, counts, time, arrivals);
  Rgb sum;
  for (const Arrival& a : arrivals) sum += a.irradiance;
  return sum;
}

Rgb SceneLights::sampleArea(int k, const RenderScene& scene, const SurfaceHit& hit, Point2 u,
                            RayCounts& counts, double bsdfPerLight, double time) const {
  const LightSample s = sampleLight(lights_[areaLights_[k]], hit.position, hit.normal, u.x, u.y);
  if (!s.found()) return {};
  ++counts.shadow;
  if (scene.occludedAlong(scene.spawn(hit, s.direction), s.direction, time)) return {};
  return s.irradiance * powerHeuristic(s.pdf, bsdfPerLight * s.cosTheta / M_PI);
}

Rgb SceneLights::sampleIrradiance(const RenderScene& scene, const SurfaceHit& hit, Sampler& sampler,
                                  RayCounts& counts, double bsdfPerLight, double time) const {
  Rgb sum = deltaIrradiance(scene, hit, counts, time);
  for (int k = 0; k < areaCount(); ++k)
    sum += sampleArea(k, scene, hit, sampler.get2D(), counts, bsdfPerLight, time);
  return sum;
}

Rgb SceneLights::escapedRadiance(const Eigen::Vector3d& direction) const {
  Rgb sum;
  for (const int k : areaLights_) sum += radianceAlong(lights_[k], direction);
  return sum;
}

Rgb SceneLights::escapedRadiance(const Eigen::Vector3d& direction, const Eigen::Vector3d& normal,
                                 double bsdfPerLight) const {
  const double bsdfPdf = std::max(0.0, normal.dot(direction)) / M_PI;
  Rgb sum;
  for (const int k : areaLights_) {
    const Light& light = lights_[k];
    const Rgb radiance = radianceAlong(light, direction);
    if (!radiance.isZero())
      sum += radiance * powerHeuristic(bsdfPerLight * bsdfPdf, lightPdf(light, normal, direction));
  }
  return sum;
}

Rgb SceneLights::unshadowedIrradiance(const Eigen::Vector3d& x, const Eigen::Vector3d& n) const {
  Rgb sum;
  for (const Light& light : lights_) sum += rad::unshadowedIrradiance(light, x, n);
  return sum;
}

}  // namespace rad
