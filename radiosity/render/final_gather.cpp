#include "radiosity/render/final_gather.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "radiosity/core/rng.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/pipeline/emitter_first_shot.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/render/scattering.h"
#include "radiosity/render/sobol_sampler.h"
#include "radiosity/scene/surface_textures.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {
namespace {

// The variance of the mean of n samples of sum `sum` and sum of squares `squares`: s²/n, s² the
// unbiased sample variance (the second moment itself for a single sample).
Rgb varianceOfMean(const Rgb& sum, const Rgb& squares, int n) {
  Rgb v;
  if (n <= 0) return v;
  for (int c = 0; c < 3; ++c) {
    const double spread = squares[c] - sum[c] * sum[c] / n;
    v[c] = n > 1 ? std::max(0.0, spread) / (double(n) * (n - 1)) : squares[c];
  }
  return v;
}

// Shadow rays per element for its mean direct light (indirectFromSolution): the solve's own
// first shot takes half its 1024 default links' rays (EmitterFirstShot::raysForSolve); the
// mean's noise enters the indirect part, so about as many.
constexpr int kMeanDirectRays = 512;

// An interpolated indirect part may dip below 0 where noise put an element's below its direct
// share; the light reflected at a point never does.
Rgb nonNegative(Rgb light) {
  for (int c = 0; c < 3; ++c) light[c] = std::max(0.0, light[c]);
  return light;
}

// Calls fn(hit, k) at each of `points` Sobol points k (stream `key`) of element e that lies in its
// exposed part (element_exposure.h), `hit` placed there, facing out of the element's front; the
// number of such points. The solution's B is over the exposed part: so are the means over it.
template <class Fn>
int forEachExposedPoint(const RenderScene& scene, const ElementExposure& exposure, int e,
                        int points, uint64_t key, Fn&& fn) {
  const PatchMesh& mesh = scene.mesh();
  const auto c = mesh.corners(e);
  SurfaceHit hit;
  hit.element = e;
  hit.normal = mesh.normal(e);
  hit.front = true;
  hit.material = &scene.material(e);
  int exposed = 0;
  for (int k = 0; k < points; ++k) {
    const Point2 p = SobolSampler::point(k, streamKey(key, e, 1));
    if (exposure.buried(e, p.x, p.y)) continue;
    ++exposed;
    const double r = std::sqrt(p.x);
    hit.position = (1 - r) * c[0] + r * (1 - p.y) * c[1] + r * p.y * c[2];
    fn(static_cast<const SurfaceHit&>(hit), k);
  }
  return exposed;
}

std::vector<double> exposedAreas(const PatchMesh& mesh, const ElementExposure& exposure) {
  std::vector<double> areas(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    areas[e] = mesh.area(e) * exposure.exposedFraction(e);
  return areas;
}

}  // namespace

FinalGather::FinalGather(const RenderScene& scene, const std::vector<Rgb>& radiosity,
                         FinalGatherOptions options)
    : scene_(scene),
      options_(options),
      exposure_(scene.mesh(), scene.caster()),
      interpolation_(scene.mesh(), exposedAreas(scene.mesh(), exposure_)) {
  const int n = scene.mesh().elementCount();
  radiance_.resize(n);
  reflected_.resize(n);
  emitted_.resize(n);
  rho_.resize(n);
  std::vector<Eigen::Vector3d> perElement(n);
  for (int e = 0; e < n; ++e) {
    const Rgb b = radiosity.at(e);
    emitted_[e] = elementEmission(scene.scene(), scene.mesh(), e);
    rho_[e] = elementReflectance(scene.scene(), scene.mesh(), e);
    const Rgb emitted = M_PI * emitted_[e];
    radiance_[e] = b / M_PI;
    // B ≥ E holds exactly for a converged solution; a solver stopped early never goes below E.
    reflected_[e] = (b - emitted) / M_PI;
    for (int c = 0; c < 3; ++c) reflected_[e][c] = std::max(0.0, reflected_[e][c]);
    perElement[e] = {radiance_[e].r, radiance_[e].g, radiance_[e].b};
  }
  if (indirectFromSolution()) {
    // The solution's reflected light less its direct part (the emitters' and the scene lights'
    // means over the element, as the hits' shadow rays estimate them), per unit reflectance.
    const std::vector<Rgb> direct = meanDirectLight();
    for (int e = 0; e < n; ++e) {
      // Not clamped at 0: where noise puts the solution's reflected light below its mean direct
      // part, the hits' own direct light makes up for it on average over the element.
      const Rgb indirect = reflected_[e] - rho_[e] * direct[e];
      Rgb h;
      for (int c = 0; c < 3; ++c)
        if (rho_[e][c] > 0) h[c] = indirect[c] / rho_[e][c];
      perElement[e] = {h.r, h.g, h.b};
    }
    vertexIndirect_ = interpolation_.interpolate(perElement);
    return;
  }
  if (options_.gatherRays == 0) {
    vertexRadiance_ = interpolation_.interpolate(perElement);
    if (!scene.scene().textures.empty()) {
      for (int e = 0; e < n; ++e) {
        const Rgb h = incidentLight(radiance_[e], emitted_[e], rho_[e]);
        perElement[e] = {h.r, h.g, h.b};
      }
      vertexIncident_ = interpolation_.interpolate(perElement);
    }
    return;
  }
  elementSize_.resize(n);
  for (int e = 0; e < n; ++e) elementSize_[e] = std::sqrt(scene.mesh().area(e));
  // Not clamped at 0: where the solution's reflected light is below the element's mean shadow-ray
  // share, the point's own share makes up for it on average.
  ElementLight direct = meanLightSample();
  indirect_.resize(n);
  for (int e = 0; e < n; ++e) indirect_[e] = reflected_[e] - rho_[e] * direct.mean[e];
  uniformLight_ = std::move(direct.uniform);
}

FinalGather::ElementLight FinalGather::meanLightSample() const {
  // Stratified over the element (one Sobol 2D dimension) and over the emitters (another): 256
  // points, as many as the solve's default hemisphere rays per element, so the mean's noise is of
  // the order of the solution's own.
  constexpr int kPoints = 256;
  const PatchMesh& mesh = scene_.mesh();
  const int n = mesh.elementCount();
  ElementLight light{std::vector<Rgb>(n), std::vector<char>(n, 1)};
  if (scene_.emitters().empty()) return light;
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& range) {
    RayCounts unused;
    for (int e = range.begin(); e < range.end(); ++e) {
      if (scene_.material(e).isSpecular() || rho_[e].maxComponent() == 0) continue;
      Rgb sum;
      int lit = 0;
      const int exposed = forEachExposedPoint(
          scene_, exposure_, e, kPoints, stream_tag::kElementMean,
          [&](const SurfaceHit& hit, int k) {
            const Rgb v = lightSample(
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

std::vector<Rgb> FinalGather::meanDirectLight() const {
  const PatchMesh& mesh = scene_.mesh();
  const int n = mesh.elementCount();
  std::vector<Rgb> direct = meanSceneLight();
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

std::vector<Rgb> FinalGather::meanSceneLight() const {
  // Fewer points than meanLightSample's: the sun and sky vary slowly over an element but for
  // shadows, and a sky costs a ray per point per light.
  constexpr int kPoints = 64;
  const PatchMesh& mesh = scene_.mesh();
  const int n = mesh.elementCount();
  std::vector<Rgb> mean(n);
  const SceneLights& lights = scene_.lights();
  if (lights.empty()) return mean;
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& range) {
    RayCounts unused;
    for (int e = range.begin(); e < range.end(); ++e) {
      if (scene_.material(e).isSpecular() || rho_[e].maxComponent() == 0) continue;
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

std::string FinalGather::name() const {
  if (indirectFromSolution())
    return "radiosity (direct by " + std::to_string(options_.lightRays) +
           " shadow rays, indirect from the solution)";
  return options_.gatherRays == 0
             ? "radiosity (interpolated, no gather)"
             : "radiosity (final gather, " + std::to_string(options_.gatherRays) + " rays)";
}

Rgb FinalGather::interpolatedIndirect(int element, double u, double v) const {
  const auto& t = interpolation_.triangle(element);
  const Eigen::Vector3d h =
      (1 - u - v) * vertexIndirect_[t[0]] + u * vertexIndirect_[t[1]] + v * vertexIndirect_[t[2]];
  return {h.x(), h.y(), h.z()};
}

Rgb FinalGather::interpolatedRadiance(const SurfaceHit& hit) const {
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

// Multiple importance sampling (power heuristic, one light and one gather sample per pair): near
// corners the emitter-area estimator alone is heavy-tailed (cos·cos/d² grows without bound),
// and the cosine-sampled gather rays cover exactly those directions well.
double FinalGather::misWeight(double pdfA, double pdfB) {
  const double a = pdfA * pdfA, b = pdfB * pdfB;
  return a / (a + b);
}

Rgb FinalGather::lightSample(const SurfaceHit& hit, Point2 u, RayCounts& counts,
                             double gathersPerLight) const {
  const EmitterSample s = scene_.emitters().sample(u.x, u.y);
  if (s.element < 0 || s.element == hit.element) return {};
  Eigen::Vector3d w = s.position - hit.position;
  const double d2 = w.squaredNorm();
  w /= std::sqrt(d2);
  const double cosX = hit.normal.dot(w), cosY = -s.normal.dot(w);
  if (cosX <= 0 || cosY <= 0) return {};  // behind the receiver, or the emitter's back
  ++counts.shadow;
  if (scene_.occluded(scene_.spawn(hit, w), s.position)) return {};
  const double lightPdf = s.pdfArea * d2 / cosY;  // per solid angle
  return s.radiance * (cosX / lightPdf * misWeight(lightPdf, gathersPerLight * cosX / M_PI) / M_PI);
}

void FinalGather::spreadOrigins(const SurfaceHit& hit, const TexelFootprint* footprint,
                                Sampler& sampler, int count,
                                std::vector<Eigen::Vector3d>& out) const {
  out.clear();
  if (footprint == nullptr || footprint->isPoint()) return;
  thread_local std::vector<Point2> spots;
  sampler.get2DArray(count, spots);
  const auto c = scene_.mesh().corners(hit.element);
  out.resize(count);
  for (int k = 0; k < count; ++k) {
    const Eigen::Vector3d b = footprint->at(spots[k].x, spots[k].y);
    out[k] = b[0] * c[0] + b[1] * c[1] + b[2] * c[2];
  }
}

Rgb FinalGather::directLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                             Rgb* variance, const TexelFootprint* footprint) const {
  thread_local std::vector<Point2> points;
  thread_local std::vector<Eigen::Vector3d> origins;
  SurfaceHit at = hit;  // where each sample leaves from: hit, or its own point of the footprint
  const int n = lightRays();
  sampler.get2DArray(n, points);
  spreadOrigins(hit, footprint, sampler, n, origins);
  Rgb sum, squares;
  // indirectFromSolution: as many cosine rays as shadow rays, which only look for the lights.
  const double gathersPerLight = indirectFromSolution() ? 1.0 : double(options_.gatherRays) / n;
  for (int k = 0; k < n; ++k) {
    if (!origins.empty()) at.position = origins[k];
    const Rgb v = lightSample(at, points[k], counts, gathersPerLight);
    sum += v;
    if (variance) squares += v * v;
  }
  if (variance) *variance += varianceOfMean(sum, squares, n);
  sum = sum / n;
  // The point, spot, directional and sky lights: the delta ones once (exact) at one point, at
  // about n / (their count) points over a footprint (so about n shadow rays in all); the sun's
  // disc and the sky by n samples each, stratified, in the same MIS pair with the gather rays.
  const SceneLights& lights = scene_.lights();
  if (lights.empty()) return sum;  // irradiance / π: times ρ it is the reflected radiance
  Rgb fromLights;
  const int deltaPoints = std::max(1, n / std::max(1, lights.deltaCount()));
  if (lights.deltaCount() > 0)
    spreadOrigins(hit, footprint, sampler, deltaPoints, origins);
  else
    origins.clear();
  if (origins.empty()) {
    fromLights = lights.deltaIrradiance(scene_, hit, counts);
  } else {
    Rgb delta, deltaSquares;
    for (int k = 0; k < deltaPoints; ++k) {
      at.position = origins[k];
      const Rgb v = lights.deltaIrradiance(scene_, at, counts);
      delta += v;
      if (variance) deltaSquares += v * v;
    }
    if (variance) *variance += varianceOfMean(delta, deltaSquares, deltaPoints) / (M_PI * M_PI);
    fromLights = delta / deltaPoints;
  }
  for (int a = 0; a < lights.areaCount(); ++a) {
    sampler.get2DArray(n, points);
    spreadOrigins(hit, footprint, sampler, n, origins);
    Rgb area, areaSquares;
    for (int k = 0; k < n; ++k) {
      if (!origins.empty()) at.position = origins[k];
      const Rgb v = lights.sampleArea(a, scene_, at, points[k], counts, gathersPerLight);
      area += v;
      if (variance) areaSquares += v * v;
    }
    if (variance) *variance += varianceOfMean(area, areaSquares, n) / (M_PI * M_PI);
    fromLights += area / n;
  }
  return sum + fromLights / M_PI;
}

Rgb FinalGather::gatherLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                             Rgb* variance, const TexelFootprint* footprint) const {
  thread_local std::vector<Point2> points;
  thread_local std::vector<Eigen::Vector3d> origins;
  SurfaceHit at = hit;
  const int n = indirectFromSolution() ? lightRays() : options_.gatherRays;
  sampler.get2DArray(n, points);
  spreadOrigins(hit, footprint, sampler, n, origins);
  Rgb sum, squares;
  for (int k = 0; k < n; ++k) {
    if (!origins.empty()) at.position = origins[k];
    const Eigen::Vector3d d = cosineDirection(hit.normal, points[k].x, points[k].y);
    const Rgb v = indirectFromSolution() ? lightAlong(at, d, counts)
                                         : secondaryRadiance(at, d, sampler.rng(), counts, true);
    sum += v;
    if (variance) squares += v * v;
  }
  if (variance) *variance += varianceOfMean(sum, squares, n);
  return sum /
         n;  // cosine-weighted mean of incoming radiance: times ρ it is the reflected radiance
}

Rgb FinalGather::lightAlong(const SurfaceHit& from, const Eigen::Vector3d& direction,
                            RayCounts& counts) const {
  const SurfaceHit hit = scene_.intersect(scene_.spawn(from, direction), direction);
  ++counts.closest;
  if (!hit.hit()) return scene_.lights().escapedRadiance(direction, from.normal, 1.0);
  if (hit.material->isSpecular() || !hit.front || !hit.material->isEmitter()) return {};
  const double cosY = -hit.normal.dot(direction);
  const double lightPdf =
      scene_.emitters().pdfArea(hit.element) * hit.distance * hit.distance / cosY;
  return hit.material->emission * misWeight(from.normal.dot(direction) / M_PI, lightPdf);
}

Rgb FinalGather::secondaryRadiance(const SurfaceHit& from, Eigen::Vector3d direction, Rng& rng,
                                   RayCounts& counts, bool mayContinue) const {
  Eigen::Vector3d origin = scene_.spawn(from, direction);
  const double bsdfPdf = from.normal.dot(direction) / M_PI;
  Rgb weight = Rgb::all(1.0);
  bool viaSpecular = false;
  for (int depth = 0;; ++depth) {
    const SurfaceHit hit = scene_.intersect(origin, direction);
    ++counts.closest;
    if (!hit.hit()) {
      // Out of the scene: the sky and the sun, less the share the light samples at `from` took
      // (counted as the emitters' are); through mirrors and glass, all of it.
      const double gathersPerLight = mayContinue ? double(options_.gatherRays) / lightRays() : 1.0;
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
    if (viaSpecular) return weight * radiance_[hit.element];
    // Directly: the emission's share of the MIS pair with the shadow rays at `from`, plus the
    // reflected light.
    Rgb value;
    if (hit.material->isEmitter()) {
      const double cosY = -hit.normal.dot(direction);
      const double lightPdf =
          scene_.emitters().pdfArea(hit.element) * hit.distance * hit.distance / cosY;
      // From the eye hit the pair is gatherRays cosine rays against lightRays shadow rays; from
      // a continuation, one against one.
      const double gathersPerLight = mayContinue ? double(options_.gatherRays) / lightRays() : 1.0;
      value += hit.material->emission * misWeight(gathersPerLight * bsdfPdf, lightPdf);
    }
    const Rgb& rho = hit.diffuse;
    if (mayContinue && rho.maxComponent() > 0 && hit.distance < elementSize_[hit.element]) {
      // Closer than the element's size (a corner, a contact), where the element's one value is
      // least like the light at this very point: gather once more from the point, one shadow
      // ray and one cosine ray (read from the solution), weighed by MIS as at the eye hit.
      const Point2 light{rng.uniform(), rng.uniform()}, bounce{rng.uniform(), rng.uniform()};
      RandomSampler lightsSampler(rng);
      const Rgb incoming =
          lightSample(hit, light, counts) +
          scene_.lights().sampleIrradiance(scene_, hit, lightsSampler, counts, 1) / M_PI +
          secondaryRadiance(hit, cosineDirection(hit.normal, bounce.x, bounce.y), rng, counts,
                            false);
      return weight * (value + rho * incoming);
    }
    // Otherwise the solution's reflected part, (B − E)/π of the element, with its mean shadow-ray
    // share of the direct light replaced by the point's own where a shadow edge (or an emitter's
    // plane) crosses the element. Where all of the element's points saw the emitters alike, the
    // mean is kept: a far landing samples the element about evenly, so the mean is what its own
    // shadow ray would average to, without that ray's noise and cost (measured: docs/benchmarks.md,
    // "Error against time").
    if (rho_[hit.element].maxComponent() > 0 && !uniformLight_[hit.element]) {
      const Point2 light{rng.uniform(), rng.uniform()};
      value += indirect_[hit.element] + rho_[hit.element] * lightSample(hit, light, counts);
    } else {
      value += reflected_[hit.element];
    }
    return weight * value;
  }
}

Rgb FinalGather::outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                                  RayCounts& counts) const {
  Rgb unused;
  return outgoingRadiance(element, barycentric, rng, counts, unused);
}

Rgb FinalGather::outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                                  RayCounts& counts, Rgb& standardError) const {
  TexelFootprint point;
  point.centre = barycentric;
  return outgoingRadiance(element, point, rng, counts, standardError);
}

Rgb FinalGather::outgoingRadiance(int element, const TexelFootprint& footprint, Rng& rng,
                                  RayCounts& counts, Rgb& standardError) const {
  RandomSampler sampler(rng);
  return outgoingRadiance(element, footprint, sampler, counts, standardError);
}

Rgb FinalGather::outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                                  RayCounts& counts, Rgb& standardError) const {
  const PatchMesh& mesh = scene_.mesh();
  const auto c = mesh.corners(element);
  const Eigen::Vector3d& barycentric = footprint.centre;
  SurfaceHit hit;
  hit.element = element;
  hit.position = barycentric[0] * c[0] + barycentric[1] * c[1] + barycentric[2] * c[2];
  hit.u = barycentric[1];
  hit.v = barycentric[2];
  hit.diffuse = reflectanceAt(scene_.scene(), mesh, element, hit.u, hit.v);
  hit.normal = scene_.mesh().normal(element);
  hit.front = true;
  hit.material = &scene_.material(element);
  const Material& m = *hit.material;
  standardError = Rgb();
  if (m.isSpecular()) return {};
  if (hit.diffuse.maxComponent() == 0) return m.emission;
  Rgb variance;
  if (indirectFromSolution()) {
    const Rgb along = gatherLight(hit, sampler, counts, &variance, &footprint);
    const Rgb direct = along + directLight(hit, sampler, counts, &variance, &footprint);
    for (int k = 0; k < 3; ++k) standardError[k] = hit.diffuse[k] * std::sqrt(variance[k]);
    // A buried point (under a box resting on the floor) takes no interpolated light from the
    // exposed part beside it, as the interpolated bake leaves it dark.
    const Rgb indirect = exposure_.buriedAtBarycentric(element, hit.u, hit.v)
                             ? Rgb()
                             : interpolatedIndirect(element, hit.u, hit.v);
    return m.emission + hit.diffuse * nonNegative(direct + indirect);
  }
  // The gather rays draw from the rng first, then the shadow rays: the order GCC gave the
  // unsequenced sum `directLight(…) + gatherLight(…)` this was before, so bakes stay bit for bit.
  const Rgb gathered = gatherLight(hit, sampler, counts, &variance, &footprint);
  const Rgb direct = directLight(hit, sampler, counts, &variance, &footprint);
  for (int k = 0; k < 3; ++k) standardError[k] = hit.diffuse[k] * std::sqrt(variance[k]);
  return m.emission + hit.diffuse * (direct + gathered);
}

Rgb FinalGather::radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
                          RayCounts& counts) const {
  RandomSampler sampler(rng);
  return radiance(origin, direction, sampler, counts);
}

Rgb FinalGather::radiance(const Eigen::Vector3d& startOrigin, const Eigen::Vector3d& startDirection,
                          Sampler& sampler, RayCounts& counts) const {
  Eigen::Vector3d origin = startOrigin, direction = startDirection;
  Rgb weight = Rgb::all(1.0);
  for (int depth = 0;; ++depth) {
    const SurfaceHit hit = scene_.intersect(origin, direction);
    ++(depth == 0 ? counts.camera : counts.closest);
    if (!hit.hit()) return weight * scene_.lights().escapedRadiance(direction);  // the sky
    const Material& m = *hit.material;
    if (m.isSpecular()) {
      if (depth >= kSpecularBounceLimit ||
          (depth >= kSpecularRouletteAfter && !survivesRouletteWithinOne(weight, sampler.get1D())))
        return {};
      if (!continueSpecular(scene_, hit, origin, direction, weight,
                            [&] { return sampler.get1D(); }))
        return {};
      continue;
    }
    if (!hit.front) return {};
    if (options_.gatherRays == 0 && !indirectFromSolution())
      return weight * interpolatedRadiance(hit);
    if (hit.diffuse.maxComponent() == 0) {
      // Nothing to reflect (a black emitter, say): its radiance is Ke, no gather needed.
      ++counts.gathersSkipped;
      return weight * m.emission;
    }
    if (indirectFromSolution()) {
      // In sequence, so that every compiler draws the points alike: the cosine rays first, then
      // the shadow rays, as the gather below draws them.
      const Rgb along = gatherLight(hit, sampler, counts);
      const Rgb direct = directLight(hit, sampler, counts);
      return weight * (m.emission +
                       hit.diffuse * nonNegative(direct + along +
                                                 interpolatedIndirect(hit.element, hit.u, hit.v)));
    }
    const Rgb reflected = directLight(hit, sampler, counts) + gatherLight(hit, sampler, counts);
    return weight * (m.emission + hit.diffuse * reflected);
  }
}

}  // namespace rad
