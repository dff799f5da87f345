#include "radiosity/render/direct_indirect_split.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "radiosity/core/rng.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/pipeline/emitter_first_shot.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/render/diffuse_eye_hit.h"
#include "radiosity/render/element_solution.h"
#include "radiosity/render/scene_lights.h"

namespace rad {
namespace {

// Shadow rays per element for its mean direct light: the solve's own first shot takes half its
// 1024 default links' rays (EmitterFirstShot::raysForSolve); the mean's noise enters the indirect
// part, so about as many.
constexpr int kMeanDirectRays = 512;

// An interpolated indirect part may dip below 0 where noise put an element's below its direct
// share; the light reflected at a point never does.
Rgb nonNegative(Rgb light) {
  for (int c = 0; c < 3; ++c) light[c] = std::max(0.0, light[c]);
  return light;
}

}  // namespace

DirectIndirectSplit::DirectIndirectSplit(const RenderScene& scene,
                                         const std::vector<Rgb>& radiosity, int lightRays)
    // As many cosine rays as shadow rays, which only look for the lights.
    : scene_(scene),
      direct_(scene, lightRays, 1.0),
      exposure_(scene.mesh(), scene.caster()),
      interpolation_(scene.mesh(), exposedAreas(scene.mesh(), exposure_)) {
  const ElementSolution solution(scene, radiosity);
  // The solution's reflected light less its direct part (the emitters' and the scene lights'
  // means over the element, as the hits' shadow rays estimate them), per unit reflectance.
  const std::vector<Rgb> direct = meanDirectLight(solution.rho);
  std::vector<Rgb> perElement(direct.size());
  for (size_t e = 0; e < direct.size(); ++e) {
    const Rgb& rho = solution.rho[e];
    // Not clamped at 0: where noise puts the solution's reflected light below its mean direct
    // part, the hits' own direct light makes up for it on average over the element.
    const Rgb indirect = solution.reflected[e] - rho * direct[e];
    for (int c = 0; c < 3; ++c)
      if (rho[c] > 0) perElement[e][c] = indirect[c] / rho[c];
  }
  vertexIndirect_ = interpolation_.interpolate(asVectors(perElement));
}

std::vector<Rgb> DirectIndirectSplit::meanDirectLight(const std::vector<Rgb>& rho) const {
  const PatchMesh& mesh = scene_.mesh();
  const int n = mesh.elementCount();
  std::vector<Rgb> direct = meanSceneLight(rho);
  // The emitters' by the solve's own estimator of their first shot (emitter_first_shot.h) on the
  // solve's own problem (E and ρ as it shoots them, cut-outs too), every emitter shot, however
  // large: bounded beside an emitter, where a shadow ray's E·cos·cos/r² has no bound.
  RadiosityProblem problem = makeProblem(scene_.scene(), mesh, &exposure_);
  EmitterFirstShot shot(mesh, scene_.caster(), exposure_, stream_tag::kSplitDirect, kMeanDirectRays,
                        /*largeEmitterShare=*/1.0);
  shot.apply(problem);
  if (shot.active())
    for (int e = 0; e < n; ++e) direct[e] += shot.irradiance()[e] / M_PI;
  return direct;
}

std::vector<Rgb> DirectIndirectSplit::meanSceneLight(const std::vector<Rgb>& rho) const {
  // Fewer points than the gather's element means: the sun and sky vary slowly over an element
  // but for shadows, and a sky costs a ray per point per light.
  constexpr int kPoints = 64;
  const PatchMesh& mesh = scene_.mesh();
  const int n = mesh.elementCount();
  std::vector<Rgb> mean(n);
  const SceneLights& lights = scene_.lights();
  if (lights.empty()) return mean;
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& range) {
    RayCounts unused;
    for (int e = range.begin(); e < range.end(); ++e) {
      if (scene_.material(e).isSpecular() || rho[e].maxComponent() == 0) continue;
      Rgb sum;
      const int exposed = forEachExposedPoint(
          scene_, exposure_, e, kPoints, stream_tag::kLightMean, [&](const SurfaceHit& hit, int k) {
            sum += lights.deltaIrradiance(scene_, hit, unused);
            for (int a = 0; a < lights.areaCount(); ++a)
              sum += lights.sampleArea(
                  a, scene_, hit,
                  SobolSampler::point(k, streamKey(stream_tag::kLightMean, e, 2 + a)), unused, 0.0);
          });
      mean[e] = exposed > 0 ? sum / (exposed * M_PI) : Rgb();
    }
  });
  return mean;
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
                                  Rng& rng, RayCounts& counts) const {
  RandomSampler sampler(rng);
  return radiance(origin, direction, sampler, counts);
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
