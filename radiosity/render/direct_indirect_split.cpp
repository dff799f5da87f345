#include "radiosity/render/direct_indirect_split.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/rng.h"
#include "radiosity/render/diffuse_eye_hit.h"
#include "radiosity/render/element_solution.h"
#include "radiosity/render/scene_lights.h"

namespace rad {
namespace {

// An interpolated indirect part may dip below 0 where noise put an element's below its direct
// share; the light reflected at a point never does.
Rgb nonNegative(Rgb light) {
  for (int c = 0; c < 3; ++c) light[c] = std::max(0.0, light[c]);
  return light;
}

}  // namespace

DirectIndirectSplit::DirectIndirectSplit(const RenderScene& scene,
                                         const std::vector<Rgb>& radiosity,
                                         const std::vector<Rgb>& directIrradiance, int lightRays)
    // As many cosine rays as shadow rays, which only look for the lights.
    : scene_(scene),
      direct_(scene, lightRays, 1.0),
      exposure_(scene.mesh(), scene.caster()),
      interpolation_(scene.mesh(), exposedAreas(scene.mesh(), exposure_)) {
  RAD_CHECK_MSG(directIrradiance.size() == radiosity.size(),
                "the direct/indirect split needs the solve's E_d per element");
  const ElementSolution solution(scene, radiosity);
  // The solution's reflected light less its direct part, per unit reflectance: B − E − ρ E_d, the
  // E_d the solve itself computed (Solution::directIrradiance), so the indirect part is the
  // solver's own, its direct light's noise cancelled.
  std::vector<Rgb> perElement(radiosity.size());
  for (size_t e = 0; e < radiosity.size(); ++e) {
    const Rgb& rho = solution.rho[e];
    if (scene_.material(static_cast<int>(e)).isSpecular()) continue;
    // Not clamped at 0: where rounding puts the reflected light below its direct part, the
    // hits' own direct light makes up for it on average over the element.
    const Rgb indirect = solution.reflected[e] - rho * (directIrradiance[e] / M_PI);
    for (int c = 0; c < 3; ++c)
      if (rho[c] > 0) perElement[e][c] = indirect[c] / rho[c];
  }
  vertexIndirect_ = interpolation_.interpolate(asVectors(perElement));
}

std::string DirectIndirectSplit::name() const {
  return "radiosity (direct by " + std::to_string(direct_.lightRays()) +
         " shadow rays, indirect from the solution)";
}

Rgb DirectIndirectSplit::interpolatedIndirect(int element, double u, double v) const {
  const auto& t = interpolation_.triangle(element);
  const Eigen::Vector3d h =
      (1 - u - v) * vertexIndirect_[t[0]] + u * vertexIndirect_[t[1]] + v * vertexIndirect_[t[2]];
  return {h.x(), h.y(), h.z()};
}

Rgb DirectIndirectSplit::lightsAlong(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                                     Rgb* variance, const TexelFootprint* footprint) const {
  return direct_.cosineMean(hit, direct_.lightRays(), sampler, variance, footprint,
                            [&](const SurfaceHit& from, const Eigen::Vector3d& d) {
                              return lightAlong(from, d, counts);
                            });
}

Rgb DirectIndirectSplit::lightAlong(const SurfaceHit& from, const Eigen::Vector3d& direction,
                                    RayCounts& counts) const {
  const SurfaceHit hit = scene_.intersect(scene_.spawn(from, direction), direction);
  ++counts.closest;
  if (!hit.hit()) return scene_.lights().escapedRadiance(direction, from.normal, 1.0);
  if (hit.material->isSpecular() || !hit.front || !hit.material->isEmitter()) return {};
  const double cosY = -hit.normal.dot(direction);
  const double lightPdf =
      scene_.emitters().pdfArea(hit.element) * hit.distance * hit.distance / cosY;
  return hit.material->emission *
         DirectLightEstimator::misWeight(from.normal.dot(direction) / M_PI, lightPdf);
}

Rgb DirectIndirectSplit::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  Sampler& sampler, RayCounts& counts) const {
  const DiffuseEyeHit eye = traceToDiffuse(scene_, origin, direction, sampler, counts);
  if (!eye.reached) return eye.radiance;
  const SurfaceHit& hit = eye.hit;
  const Material& m = *hit.material;
  if (hit.diffuse.maxComponent() == 0) {
    // Nothing to reflect (a black emitter, say): its radiance is Ke, no ray needed.
    ++counts.gathersSkipped;
    return eye.weight * m.emission;
  }
  // In sequence, so that every compiler draws the points alike: the cosine rays first, then the
  // shadow rays, as the final gather draws them.
  const Rgb along = lightsAlong(hit, sampler, counts);
  const Rgb direct = direct_.directLight(hit, sampler, counts);
  return eye.weight *
         (m.emission + hit.diffuse * nonNegative(direct + along +
                                                 interpolatedIndirect(hit.element, hit.u, hit.v)));
}

Rgb DirectIndirectSplit::outgoingRadiance(int element, const TexelFootprint& footprint,
                                          Sampler& sampler, RayCounts& counts,
                                          Rgb& standardError) const {
  const SurfaceHit hit = texelHit(scene_, element, footprint.centre);
  const Material& m = *hit.material;
  standardError = Rgb();
  if (m.isSpecular()) return {};
  if (hit.diffuse.maxComponent() == 0) return m.emission;
  Rgb variance;
  const Rgb along = lightsAlong(hit, sampler, counts, &variance, &footprint);
  const Rgb direct = along + direct_.directLight(hit, sampler, counts, &variance, &footprint);
  for (int k = 0; k < 3; ++k) standardError[k] = hit.diffuse[k] * std::sqrt(variance[k]);
  // A buried point (under a box resting on the floor) takes no interpolated light from the
  // exposed part beside it, as the interpolated bake leaves it dark.
  const Rgb indirect = exposure_.buriedAtBarycentric(element, hit.u, hit.v)
                           ? Rgb()
                           : interpolatedIndirect(element, hit.u, hit.v);
  return m.emission + hit.diffuse * nonNegative(direct + indirect);
}

}  // namespace rad
