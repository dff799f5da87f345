#include "radiosity/render/scene_lights.h"

#include <algorithm>
#include <cmath>

#include "radiosity/render/render_scene.h"
#include "radiosity/render/scattering.h"
#include "radiosity/scene/light_shapes.h"

namespace rad {
namespace {

// Power heuristic for one strategy of density `a` against another of density `b` (each already
// multiplied by its count of rays).
double powerHeuristic(double a, double b) { return a > 0 ? a * a / (a * a + b * b) : 0.0; }

bool isDelta(const Light& light) {
  return light.type == LightType::Point || light.type == LightType::Spot ||
         (light.type == LightType::Directional && light.angularDiameterDegrees <= 0);
}

// E⊥ cosθ at (x, n) from a point or spot light, 0 behind the surface or outside the cone; sets
// `toLight` (unit) and `distance`.
Rgb pointIrradiance(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                    Eigen::Vector3d& toLight) {
  toLight = light.position - x;
  const double r2 = toLight.squaredNorm();
  if (!(r2 > 0) || !std::isfinite(r2)) return {};  // on the point, or too far for a double
  toLight /= std::sqrt(r2);
  const double cosTheta = n.dot(toLight);
  if (!(cosTheta > 0)) return {};
  const double falloff =
      light.type == LightType::Spot ? spotFalloff(light, light.direction.dot(-toLight)) : 1.0;
  return light.intensity * (falloff * cosTheta / r2);
}

}  // namespace

SceneLights::SceneLights(const std::vector<Light>& lights) : lights_(lights) {
  for (size_t k = 0; k < lights_.size(); ++k)
    (isDelta(lights_[k]) ? deltaLights_ : areaLights_).push_back(static_cast<int>(k));
}

void SceneLights::deltaArrivals(const RenderScene& scene, const SurfaceHit& hit, RayCounts& counts,
                                double time, std::vector<Arrival>& out) const {
  out.clear();
  for (const int k : deltaLights_) {
    const Light& light = lights_[k];
    Arrival a;
    if (light.type == LightType::Directional) {
      a.direction = -light.direction;
      const double cosTheta = hit.normal.dot(a.direction);
      if (!(cosTheta > 0)) continue;
      ++counts.shadow;
      if (scene.occludedAlong(scene.spawn(hit, a.direction), a.direction, time)) continue;
      a.irradiance = light.irradiance * cosTheta;
    } else {
      a.irradiance = pointIrradiance(light, hit.position, hit.normal, a.direction);
      if (a.irradiance.isZero()) continue;
      ++counts.shadow;
      if (scene.occluded(scene.spawn(hit, a.direction), light.position, time)) continue;
    }
    out.push_back(a);
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
  const Light& light = lights_[areaLights_[k]];
  Eigen::Vector3d w;
  Rgb radiance;
  double lightPdf = 0;
  if (light.type == LightType::Directional) {
    w = sunDirection(light, u.x, u.y);
    radiance = sunRadiance(light);
    lightPdf = 1 / sunSolidAngle(light);
  } else if (light.map) {  // an environment or a clear sky: by its map's luminance
    w = light.map->sample(u.x, u.y, lightPdf);
    radiance = skyRadiance(light, w);
    lightPdf = light.map->pdf(w);  // the texel `radiance` came from, should rounding move w
  } else {  // the sky: cosine-weighted about the normal; the ground below the horizon is black
    w = cosineDirection(hit.normal, u.x, u.y);
    radiance = skyRadiance(light, w);
    lightPdf = std::max(0.0, hit.normal.dot(w)) / M_PI;
  }
  const double cosTheta = hit.normal.dot(w);
  if (!(cosTheta > 0) || radiance.isZero() || !(lightPdf > 0)) return {};
  ++counts.shadow;
  if (scene.occludedAlong(scene.spawn(hit, w), w, time)) return {};
  const double weight = powerHeuristic(lightPdf, bsdfPerLight * cosTheta / M_PI);
  return radiance * (cosTheta / lightPdf * weight);
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
  for (const int k : areaLights_) {
    const Light& light = lights_[k];
    if (light.type != LightType::Directional)
      sum += skyRadiance(light, direction);
    else if (insideSunDisc(light, direction))
      sum += sunRadiance(light);
  }
  return sum;
}

Rgb SceneLights::escapedRadiance(const Eigen::Vector3d& direction, const Eigen::Vector3d& normal,
                                 double bsdfPerLight) const {
  const double bsdfPdf = std::max(0.0, normal.dot(direction)) / M_PI;
  Rgb sum;
  for (const int k : areaLights_) {
    const Light& light = lights_[k];
    if (light.map)  // sampled by its map: the light sample's density there
      sum += skyRadiance(light, direction) *
             powerHeuristic(bsdfPerLight * bsdfPdf, light.map->pdf(direction));
    else if (light.type == LightType::Sky)
      sum += skyRadiance(light, direction) * powerHeuristic(bsdfPerLight * bsdfPdf, bsdfPdf);
    else if (insideSunDisc(light, direction))
      sum += sunRadiance(light) * powerHeuristic(bsdfPerLight * bsdfPdf, 1 / sunSolidAngle(light));
  }
  return sum;
}

Rgb SceneLights::unshadowedIrradiance(const Eigen::Vector3d& x, const Eigen::Vector3d& n) const {
  Rgb sum;
  for (const Light& light : lights_) {
    switch (light.type) {
      case LightType::Point:
      case LightType::Spot: {
        Eigen::Vector3d toLight;
        sum += pointIrradiance(light, x, n, toLight);
        break;
      }
      case LightType::Directional:
        sum += light.irradiance * std::max(0.0, n.dot(-light.direction));
        break;
      case LightType::Sky:
      case LightType::Environment:
        sum += skyIrradiance(light, n);
        break;
    }
  }
  return sum;
}

}  // namespace rad
