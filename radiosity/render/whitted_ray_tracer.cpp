#include "radiosity/render/whitted_ray_tracer.h"

#include <cmath>

#include "radiosity/core/fresnel.h"
#include "radiosity/render/scattering.h"

namespace rad {

WhittedRayTracer::WhittedRayTracer(const RenderScene& scene, WhittedOptions options)
    : scene_(scene), options_(options), lights_(emitterPointLights(scene)) {}

Rgb WhittedRayTracer::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                               Rng& rng, RayCounts& counts) const {
  ++counts.camera;
  return trace(origin, direction, 0, 1.0, rng, counts);
}

Rgb WhittedRayTracer::trace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                            int depth, double weight, Rng& rng, RayCounts& counts) const {
  const SurfaceHit hit = scene_.intersect(origin, direction);
  if (!hit.hit()) return scene_.lights().escapedRadiance(direction);
  const Material& m = *hit.material;

  if (m.kind == SurfaceKind::Mirror) {
    if (!hit.front || depth >= options_.maxDepth) return {};
    const Eigen::Vector3d d = reflect(direction, hit.normal);
    const double w = weight * m.specular.maxComponent();
    if (w < options_.minWeight) return {};
    ++counts.closest;
    return m.specular * trace(scene_.spawn(hit, d), d, depth + 1, w, rng, counts);
  }
  if (m.kind == SurfaceKind::Dielectric) {
    if (depth >= options_.maxDepth) return {};
    // The same optics as scatterSpecular, but both branches are followed with their weights.
    const bool entering = hit.front;
    const Eigen::Vector3d n = entering ? hit.normal : Eigen::Vector3d(-hit.normal);
    const double etaI = entering ? 1.0 : m.ior, etaT = entering ? m.ior : 1.0;
    const double cosI = -direction.dot(n);
    const double f = fresnelDielectric(cosI, etaI, etaT);
    Rgb result;
    if (weight * f >= options_.minWeight) {
      const Eigen::Vector3d d = reflect(direction, n);
      ++counts.closest;
      result += f * trace(scene_.spawn(hit, d), d, depth + 1, weight * f, rng, counts);
    }
    const double eta = etaI / etaT;
    const Rgb t = m.transmittance * ((1 - f) * eta * eta);
    if (f < 1 && weight * t.maxComponent() >= options_.minWeight) {
      const double cosT = std::sqrt(std::max(0.0, 1 - eta * eta * (1 - cosI * cosI)));
      const Eigen::Vector3d d = (eta * direction + (eta * cosI - cosT) * n).normalized();
      ++counts.closest;
      result +=
          t * trace(scene_.spawn(hit, d), d, depth + 1, weight * t.maxComponent(), rng, counts);
    }
    return result;
  }

  if (!hit.front) return {};  // back faces are black, as in the radiosity pass
  Rgb result = m.emission;
  if (hit.diffuse.maxComponent() == 0) return result;
  const int patch = scene_.mesh().patch(hit.element);
  Rgb irradiance;
  for (const PointLight& light : lights_) {
    if (light.patch == patch) continue;
    const Rgb e = light.irradiance(hit.position, hit.normal);
    if (e.maxComponent() == 0) continue;
    ++counts.shadow;
    const Eigen::Vector3d w = (light.position - hit.position).normalized();
    if (!scene_.occluded(scene_.spawn(hit, w), light.position)) irradiance += e;
  }
  if (!scene_.lights().empty()) {
    RandomSampler sampler(rng);  // no scattered rays to weigh against: the samples take it all
    irradiance += scene_.lights().sampleIrradiance(scene_, hit, sampler, counts, 0);
  }
  return result + hit.diffuse * irradiance * (1.0 / M_PI);
}

}  // namespace rad
