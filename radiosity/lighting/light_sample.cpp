#include "radiosity/lighting/light_sample.h"

#include <algorithm>
#include <cmath>

#include "radiosity/core/hemisphere.h"
#include "radiosity/scene/light_shapes.h"

namespace rad {
namespace {

// A point or spot light: towards its position, E⊥ = I × falloff / r².
LightSample samplePointLight(const Light& light, const Eigen::Vector3d& x,
                             const Eigen::Vector3d& n) {
  LightSample s;
  s.delta = true;
  s.pdf = 1;
  Eigen::Vector3d toLight = light.position - x;
  const double r2 = toLight.squaredNorm();
  if (!(r2 > 0) || !std::isfinite(r2)) return s;  // on the point, or too far for a double
  s.distance = std::sqrt(r2);
  s.direction = toLight / s.distance;
  const double falloff =
      light.type == LightType::Spot ? spotFalloff(light, light.direction.dot(-s.direction)) : 1.0;
  if (!(falloff > 0)) return s;
  s.radiance = light.intensity * (falloff / r2);
  s.cosTheta = n.dot(s.direction);
  if (s.cosTheta > 0) s.irradiance = light.intensity * (falloff * s.cosTheta / r2);
  return s;
}

// A hard sun: its direction, E⊥ its irradiance.
LightSample sampleHardSun(const Light& light, const Eigen::Vector3d& n) {
  LightSample s;
  s.delta = true;
  s.pdf = 1;
  s.direction = -light.direction;
  s.radiance = light.irradiance;
  s.cosTheta = n.dot(s.direction);
  if (s.cosTheta > 0) s.irradiance = light.irradiance * s.cosTheta;
  return s;
}

// An area light at infinity, its direction and density chosen: the rest follows.
LightSample areaSample(const Light& light, const Eigen::Vector3d& n, const Eigen::Vector3d& w,
                       double pdf) {
  LightSample s;
  s.direction = w;
  s.pdf = pdf;
  s.radiance = radianceAlong(light, w);
  s.cosTheta = n.dot(w);
  if (s.cosTheta > 0 && pdf > 0 && !s.radiance.isZero())
    s.irradiance = s.radiance * (s.cosTheta / pdf);
  return s;
}

}  // namespace

bool isDeltaLight(const Light& light) {
  return light.type == LightType::Point || light.type == LightType::Spot ||
         (light.type == LightType::Directional && light.angularDiameterDegrees <= 0);
}

LightSample sampleLight(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                        double u1, double u2) {
  switch (light.type) {
    case LightType::Point:
    case LightType::Spot:
      return samplePointLight(light, x, n);
    case LightType::Directional:
      if (isDeltaLight(light)) return sampleHardSun(light, n);
      return areaSample(light, n, sunDirection(light, u1, u2), 1 / sunSolidAngle(light));
    case LightType::Sky:
    case LightType::Environment:
      break;
  }
  if (light.map) {  // an environment or a clear sky: by the map's luminance
    double pdf = 0;
    const Eigen::Vector3d w = light.map->sample(u1, u2, pdf);
    return areaSample(light, n, w, light.map->pdf(w));  // the texel the radiance comes from
  }
  // The other skies: cosine-weighted about the normal, so L cosθ / pdf = π L exactly.
  LightSample s = areaSample(light, n, Frame(n).toWorld(cosineWeightedDirection(u1, u2)), 0);
  s.pdf = std::max(0.0, s.cosTheta) / M_PI;
  if (s.cosTheta > 0) s.irradiance = s.radiance * M_PI;
  return s;
}

double lightPdf(const Light& light, const Eigen::Vector3d& n, const Eigen::Vector3d& w) {
  if (isDeltaLight(light)) return 0;
  if (light.type == LightType::Directional)
    return insideSunDisc(light, w) ? 1 / sunSolidAngle(light) : 0;
  if (light.map) return light.map->pdf(w);
  return std::max(0.0, n.dot(w)) / M_PI;
}

Rgb radianceAlong(const Light& light, const Eigen::Vector3d& w) {
  if (isDeltaLight(light)) return {};
  if (light.type == LightType::Directional)
    return insideSunDisc(light, w) ? sunRadiance(light) : Rgb();
  return skyRadiance(light, w);
}

Rgb unshadowedIrradiance(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n) {
  switch (light.type) {
    case LightType::Point:
    case LightType::Spot:
      return samplePointLight(light, x, n).irradiance;
    case LightType::Directional:
      return sampleHardSun(light, n).irradiance;  // the disc's centre
    case LightType::Sky:
    case LightType::Environment:
      return skyIrradiance(light, n);
  }
  return {};
}

}  // namespace rad
