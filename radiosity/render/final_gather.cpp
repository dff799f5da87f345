#include "radiosity/render/final_gather.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/rng.h"
#include "radiosity/core/russian_roulette.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/render/diffuse_eye_hit.h"
#include "radiosity/render/scattering.h"
#include "radiosity/render/scene_lights.h"
#include "radiosity/render/sobol_sampler.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

FinalGather::FinalGather(const RenderScene& scene, const std::vector<Rgb>& radiosity,
                         FinalGatherOptions options)
    // The MIS pair is gatherRays cosine rays against shadowRays() shadow rays.
    : scene_(scene),
      gatherRays_(options.gatherRays),
      direct_(scene, options.shadowRays(), double(options.gatherRays) / options.shadowRays()),
      solution_(scene, radiosity) {
  RAD_CHECK_GT(options.gatherRays, 0);
  const int n = scene.mesh().elementCount();
  elementSize_.resize(n);
  for (int e = 0; e < n; ++e) elementSize_[e] = std::sqrt(scene.mesh().area(e));
  // Not clamped at 0: where the solution's reflected light is below the element's mean shadow-ray
  // share, the point's own share makes up for it on average.
  ElementLight direct = meanLightSample(ElementExposure(scene.mesh(), scene.caster()));
  indirect_.resize(n);
  for (int e = 0; e < n; ++e)
    indirect_[e] = solution_.reflected[e] - solution_.rho[e] * direct.mean[e];
  uniformLight_ = std::move(direct.uniform);
}

FinalGather::ElementLight FinalGather::meanLightSample(const ElementExposure& exposure) const {
  // Stratified over the element (one Sobol 2D dimension) and over the emitters (another): 256
  // points, as many as the solve's default hemisphere rays per element, so the mean's noise is of
  // the order of the solution's own.
  constexpr int kPoints = 256;
  const int n = scene_.mesh().elementCount();
  ElementLight light{std::vector<Rgb>(n), std::vector<char>(n, 1)};
  if (scene_.emitters().empty()) return light;
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& range) {
    RayCounts unused;
    for (int e = range.begin(); e < range.end(); ++e) {
      if (scene_.material(e).isSpecular() || solution_.rho[e].maxComponent() == 0) continue;
      Rgb sum;
      int lit = 0;
      const int exposed = forEachExposedPoint(
          scene_, exposure, e, kPoints, stream_tag::kElementMean,
          [&](const SurfaceHit& hit, int k) {
            const Rgb v = direct_.lightSample(
                hit, SobolSampler::point(k, streamKey(stream_tag::kElementMean, e, 2)), unused);
            lit += v.maxComponent() > 0;
            sum += v;
          });
      light.mean[e] = exposed > 0 ? sum / exposed : Rgb();
      light.uniform[e] = lit == 0 || lit == exposed;
    }
  });
  return light;
}

std::string FinalGather::name() const {
  return "radiosity (final gather, " + std::to_string(gatherRays_) + " rays)";
}

Rgb FinalGather::gatherLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                             Rgb* variance, const TexelFootprint* footprint) const {
  // The cosine-weighted mean of incoming radiance: times ρ it is the reflected radiance.
  return direct_.cosineMean(hit, gatherRays_, sampler, variance, footprint,
                            [&](const SurfaceHit& from, const Eigen::Vector3d& d) {
                              return secondaryRadiance(from, d, sampler.rng(), counts, true);
                            });
}

Rgb FinalGather::secondaryRadiance(const SurfaceHit& from, Eigen::Vector3d direction, Rng& rng,
                                   RayCounts& counts, bool mayContinue) const {
  Eigen::Vector3d origin = scene_.spawn(from, direction);
  Rgb weight = Rgb::all(1.0);
  bool viaSpecular = false;
  for (int depth = 0;; ++depth) {
    const SurfaceHit hit = scene_.intersect(origin, direction);
    ++counts.closest;
    if (!hit.hit()) {
      // Out of the scene: the sky and the sun, less the share the light samples at `from` took
      // (counted as the emitters' are); through mirrors and glass, all of it.
      const double gathersPerLight = mayContinue ? direct_.gathersPerLight() : 1.0;
      return weight * (viaSpecular ? scene_.lights().escapedRadiance(direction)
                                   : scene_.lights().escapedRadiance(direction, from.normal,
                                                                     gathersPerLight));
    }
    if (hit.material->isSpecular()) {
      if (depth >= kSpecularBounceLimit ||
          (depth >= kSpecularRouletteAfter && !survivesRouletteWithinOne(weight, rng.uniform())))
        return {};
      if (!continueSpecular(scene_, hit, origin, direction, weight, [&] { return rng.uniform(); }))
        return {};
      viaSpecular = true;
      continue;
    }
    if (!hit.front) return {};  // back faces absorb, as in the radiosity pass
    // Through mirrors and glass (E S+ D) shadow rays cannot reach the emitter: take all of B/π.
    if (viaSpecular) return weight * solution_.radiance[hit.element];
    return weight * landing(from, hit, direction, rng, counts, mayContinue);
  }
}

Rgb FinalGather::landing(const SurfaceHit& from, const SurfaceHit& hit,
                         const Eigen::Vector3d& direction, Rng& rng, RayCounts& counts,
                         bool mayContinue) const {
  // The emission's share of the MIS pair with the shadow rays at `from`, plus the reflected
  // light.
  Rgb value;
  if (hit.material->isEmitter()) {
    const double bsdfPdf = from.normal.dot(direction) / M_PI;
    const double cosY = -hit.normal.dot(direction);
    const double lightPdf =
        scene_.emitters().pdfArea(hit.element) * hit.distance * hit.distance / cosY;
    // From the eye hit the pair is gatherRays cosine rays against lightRays shadow rays; from
    // a continuation, one against one.
    const double gathersPerLight = mayContinue ? direct_.gathersPerLight() : 1.0;
    value += hit.material->emission *
             DirectLightEstimator::misWeight(gathersPerLight * bsdfPdf, lightPdf);
  }
  const Rgb& rho = hit.diffuse;
  if (mayContinue && rho.maxComponent() > 0 && hit.distance < elementSize_[hit.element]) {
    // Closer than the element's size (a corner, a contact), where the element's one value is
    // least like the light at this very point: gather once more from the point, one shadow
    // ray and one cosine ray (read from the solution), weighed by MIS as at the eye hit.
    const Point2 light{rng.uniform(), rng.uniform()}, bounce{rng.uniform(), rng.uniform()};
    RandomSampler lightsSampler(rng);
    const Rgb incoming =
        direct_.lightSample(hit, light, counts) +
        scene_.lights().sampleIrradiance(scene_, hit, lightsSampler, counts, 1) / M_PI +
        secondaryRadiance(hit, cosineDirection(hit.normal, bounce.x, bounce.y), rng, counts, false);
    return value + rho * incoming;
  }
  // Otherwise the solution's reflected part, (B − E)/π of the element, with its mean shadow-ray
  // share of the direct light replaced by the point's own where a shadow edge (or an emitter's
  // plane) crosses the element. Where all of the element's points saw the emitters alike, the
  // mean is kept: a far landing samples the element about evenly, so the mean is what its own
  // shadow ray would average to, without that ray's noise and cost (measured: docs/benchmarks.md,
  // "Error against time").
  const int e = hit.element;
  if (solution_.rho[e].maxComponent() > 0 && !uniformLight_[e]) {
    const Point2 light{rng.uniform(), rng.uniform()};
    value += indirect_[e] + solution_.rho[e] * direct_.lightSample(hit, light, counts);
  } else {
    value += solution_.reflected[e];
  }
  return value;
}

Rgb FinalGather::outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                                  RayCounts& counts, Rgb& standardError) const {
  const SurfaceHit hit = texelHit(scene_, element, footprint.centre);
  const Material& m = *hit.material;
  standardError = Rgb();
  if (m.isSpecular()) return {};
  if (hit.diffuse.maxComponent() == 0) return m.emission;
  Rgb variance;
  // The gather rays draw from the rng first, then the shadow rays: the order GCC gave the
  // unsequenced sum `directLight(…) + gatherLight(…)` this was before, so bakes stay bit for bit.
  const Rgb gathered = gatherLight(hit, sampler, counts, &variance, &footprint);
  const Rgb direct = direct_.directLight(hit, sampler, counts, &variance, &footprint);
  for (int k = 0; k < 3; ++k) standardError[k] = hit.diffuse[k] * std::sqrt(variance[k]);
  return m.emission + hit.diffuse * (direct + gathered);
}

Rgb FinalGather::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                          Sampler& sampler, RayCounts& counts) const {
  const DiffuseEyeHit eye = traceToDiffuse(scene_, origin, direction, sampler, counts);
  if (!eye.reached) return eye.radiance;
  const SurfaceHit& hit = eye.hit;
  const Material& m = *hit.material;
  if (hit.diffuse.maxComponent() == 0) {
    // Nothing to reflect (a black emitter, say): its radiance is Ke, no gather needed.
    ++counts.gathersSkipped;
    return eye.weight * m.emission;
  }
  // Unsequenced as it always was: GCC draws the gather rays' points first (as outgoingRadiance
  // does by sequence), another compiler may not.
  const Rgb reflected =
      direct_.directLight(hit, sampler, counts) + gatherLight(hit, sampler, counts);
  return eye.weight * (m.emission + hit.diffuse * reflected);
}

}  // namespace rad
