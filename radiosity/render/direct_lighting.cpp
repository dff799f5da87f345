#include "radiosity/render/direct_lighting.h"

#include <cmath>

namespace rad {

DirectLighting::DirectLighting(const RenderScene& scene)
    : scene_(scene), lights_(emitterPointLights(scene)) {}

Rgb DirectLighting::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng&,
                             RayCounts& counts) const {
  const SurfaceHit hit = scene_.intersect(origin, direction);
  ++counts.camera;
  if (!hit.hit()) return scene_.lights().escapedRadiance(direction);  // the sky
  if (!hit.front) return {};
  const Material& m = *hit.material;
  Rgb result = m.emission;
  if (hit.diffuse.maxComponent() == 0) return result;
  const int patch = scene_.mesh().patch(hit.element);
  Rgb irradiance;
  for (const PointLight& light : lights_)
    if (light.patch != patch) irradiance += light.irradiance(hit.position, hit.normal);
  irradiance += scene_.lights().unshadowedIrradiance(hit.position, hit.normal);
  return result + hit.diffuse * irradiance * (1.0 / M_PI);
}

}  // namespace rad
