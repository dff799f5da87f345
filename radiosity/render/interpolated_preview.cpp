#include "radiosity/render/interpolated_preview.h"

#include "radiosity/render/diffuse_eye_hit.h"
#include "radiosity/render/element_solution.h"
#include "radiosity/scene/surface_textures.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

InterpolatedPreview::InterpolatedPreview(const RenderScene& scene,
                                         const std::vector<Rgb>& radiosity)
    : scene_(scene),
      exposure_(scene.mesh(), scene.caster()),
      interpolation_(scene.mesh(), exposedAreas(scene.mesh(), exposure_)) {
  ElementSolution solution(scene, radiosity);
  vertexRadiance_ = interpolation_.interpolate(asVectors(solution.radiance));
  if (!scene.scene().textures.empty()) {
    std::vector<Rgb> incident(solution.radiance.size());
    for (size_t e = 0; e < incident.size(); ++e)
      incident[e] = incidentLight(solution.radiance[e], solution.emitted[e], solution.rho[e]);
    vertexIncident_ = interpolation_.interpolate(asVectors(incident));
  }
  emitted_ = std::move(solution.emitted);
}

Rgb InterpolatedPreview::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  Sampler& sampler, RayCounts& counts) const {
  const DiffuseEyeHit eye = traceToDiffuse(scene_, origin, direction, sampler, counts);
  if (!eye.reached) return eye.radiance;
  if (exposure_.buriedAtBarycentric(eye.hit.element, eye.hit.u, eye.hit.v))
    return eye.weight * emitted_[eye.hit.element];
  return eye.weight * interpolatedRadiance(eye.hit);
}

Rgb InterpolatedPreview::interpolatedRadiance(const SurfaceHit& hit) const {
  const auto& t = interpolation_.triangle(hit.element);
  const Eigen::Vector3d v = (1 - hit.u - hit.v) * vertexRadiance_[t[0]] +
                            hit.u * vertexRadiance_[t[1]] + hit.v * vertexRadiance_[t[2]];
  // The solution is one value per element; a texture varies inside it (wood grain, tiles): the
  // light arriving there, reflected by the texel.
  if (!hasReflectanceTexture(scene_.scene(), scene_.mesh(), hit.element))
    return {v.x(), v.y(), v.z()};
  const Eigen::Vector3d h = (1 - hit.u - hit.v) * vertexIncident_[t[0]] +
                            hit.u * vertexIncident_[t[1]] + hit.v * vertexIncident_[t[2]];
  return emitted_[hit.element] + hit.diffuse * Rgb(h.x(), h.y(), h.z());
}

}  // namespace rad
