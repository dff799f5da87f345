#include "radiosity/pipeline/direct_light_stage.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "meshing/element_stream.h"
#include "radiosity/core/check.h"
#include "radiosity/core/log.h"
#include "radiosity/core/rng.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/formfactors/receiver_points.h"
#include "radiosity/pipeline/solver_results.h"
#include "radiosity/scene/light_shapes.h"

namespace rad {
namespace {

// I cosθ / r² (a spot's falloff included) at x, as if nothing were in the way; 0 behind the
// surface or outside the cone.
Rgb unshadowedPointIrradiance(const Light& light, const Eigen::Vector3d& x,
                              const Eigen::Vector3d& n) {
  const Eigen::Vector3d toLight = light.position - x;
  const double r2 = toLight.squaredNorm();
  if (!(r2 > 0) || !std::isfinite(r2)) return {};  // on the point, or too far for a double
  const double r = std::sqrt(r2);
  const double cosTheta = n.dot(toLight) / r;
  if (!(cosTheta > 0)) return {};
  const double falloff =
      light.type == LightType::Spot ? spotFalloff(light, light.direction.dot(-toLight) / r) : 1;
  if (falloff <= 0) return {};
  return light.intensity * (falloff * cosTheta / r2);
}

bool pointLightVisible(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                       const Eigen::Vector3d& n, uint64_t& raysCast) {
  const Eigen::Vector3d origin = rays.liftOff(x, n, light.position - x);
  ++raysCast;
  return !rays.occluded(origin, light.position - origin, 1.0 - 1e-6);
}

Rgb fromPointLight(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                   const Eigen::Vector3d& n, uint64_t& raysCast) {
  const Rgb e = unshadowedPointIrradiance(light, x, n);
  if (e.isZero() || !pointLightVisible(light, rays, x, n, raysCast)) return {};
  return e;
}

bool isPointLike(const Light& light) {
  return light.type == LightType::Point || light.type == LightType::Spot;
}

Rgb fromDirectional(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                    const Eigen::Vector3d& n, const DirectRays& count, uint64_t key,
                    uint64_t& raysCast) {
  const Eigen::Vector3d toSun = -light.direction;
  const double inf = std::numeric_limits<double>::infinity();
  if (light.angularDiameterDegrees <= 0) {
    const double cosTheta = n.dot(toSun);
    if (cosTheta <= 0) return {};
    ++raysCast;
    if (rays.occluded(rays.liftOff(x, n, toSun), toSun, inf)) return {};
    return light.irradiance * cosTheta;
  }
  // Directions uniform in solid angle over the sun's disc, stratified sunStrata²: the mean of
  // L cosθ / (1/Ω) with the disc's radiance L (light_shapes.h).
  Rng rng(key);
  double sum = 0;
  const int m = count.sunStrata, discRays = m * m;
  for (int k = 0; k < discRays; ++k) {
    const double u1 = (k % m + rng.uniform()) / m, u2 = (k / m + rng.uniform()) / m;
    const Eigen::Vector3d w = sunDirection(light, u1, u2);
    const double cosTheta = n.dot(w);
    if (cosTheta <= 0) continue;
    ++raysCast;
    if (!rays.occluded(rays.liftOff(x, n, w), w, inf)) sum += cosTheta;
  }
  return sunRadiance(light) * (sunSolidAngle(light) * sum / discRays);
}

Rgb fromSky(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
            const Eigen::Vector3d& n, const DirectRays& count, uint64_t key, uint64_t& raysCast) {
  const Frame frame(n);
  Rng rng(key);
  const double inf = std::numeric_limits<double>::infinity();
  Rgb open;  // the radiance of the rays that reach the sky
  const int m = count.skyStrata, skyRays = m * m;
  for (int k = 0; k < skyRays; ++k) {
    const double u1 = (k % m + rng.uniform()) / m, u2 = (k / m + rng.uniform()) / m;
    const Eigen::Vector3d w = frame.toWorld(cosineWeightedDirection(u1, u2));
    const Rgb radiance = skyRadiance(light, w);
    if (radiance.isZero()) continue;  // below the horizon: the ground is black
    ++raysCast;
    if (!rays.occluded(rays.liftOff(x, n, w), w, inf)) open += radiance;
  }
  return open * (M_PI / skyRays);
}

// A light sampled by its map (an environment, a clear sky): half the rays by the map's luminance,
// half cosine-weighted, each stratified (skyStrata × skyStrata / 2) and combined by the balance
// heuristic, so a sun in the image is found and a dim, wide map stays smooth: E = Σ L cosθ / (n
// (p_map + p_cos)) over both sets' unshadowed rays, n rays in each.
Rgb fromMap(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
            const Eigen::Vector3d& n, const DirectRays& count, uint64_t key, uint64_t& raysCast) {
  const Frame frame(n);
  Rng rng(key);
  const double inf = std::numeric_limits<double>::infinity();
  const int m = count.skyStrata, kEach = m * m / 2;
  Rgb sum;
  for (int k = 0; k < 2 * kEach; ++k) {
    const int s = k % kEach;
    const double u1 = (s % m + rng.uniform()) / m, u2 = (s / m + rng.uniform()) / (m / 2);
    double mapPdf = 0;
    const Eigen::Vector3d w = k < kEach ? light.map->sample(u1, u2, mapPdf)
                                        : frame.toWorld(cosineWeightedDirection(u1, u2));
    const double cosTheta = n.dot(w);
    if (!(cosTheta > 0)) continue;
    const Rgb radiance = skyRadiance(light, w);
    if (radiance.isZero()) continue;
    ++raysCast;
    if (rays.occluded(rays.liftOff(x, n, w), w, inf)) continue;
    sum += radiance * (cosTheta / (light.map->pdf(w) + cosTheta / M_PI));
  }
  return sum / kEach;
}

}  // namespace

Rgb directIrradiance(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                     const Eigen::Vector3d& n, uint64_t key, uint64_t& raysCast,
                     const DirectRays& count) {
  switch (light.type) {
    case LightType::Point:
    case LightType::Spot:
      return fromPointLight(light, rays, x, n, raysCast);
    case LightType::Directional:
      return fromDirectional(light, rays, x, n, count, key, raysCast);
    case LightType::Sky:
    case LightType::Environment:
      return light.map ? fromMap(light, rays, x, n, count, key, raysCast)
                       : fromSky(light, rays, x, n, count, key, raysCast);
  }
  return {};
}

Rgb sampledPointLightIrradiance(const std::vector<const Light*>& lights, const RayCaster& rays,
                                const Eigen::Vector3d& x, const Eigen::Vector3d& n, double u,
                                uint64_t& raysCast) {
  // Every light's unshadowed share is cheap (no ray); one light, picked in proportion to its
  // share's luminance, gets the shadow ray. Its share over its probability is unbiased for the
  // sum, and exact wherever all the lights see x alike.
  thread_local std::vector<Rgb> shares;
  shares.clear();
  double total = 0;
  for (const Light* light : lights) {
    shares.push_back(unshadowedPointIrradiance(*light, x, n));
    total += shares.back().luminance();
  }
  if (!(total > 0)) return {};
  double pick = u * total;
  size_t chosen = 0;
  for (size_t l = 0; l < lights.size(); ++l) {
    const double weight = shares[l].luminance();
    if (weight <= 0) continue;
    chosen = l;  // the last one with a share, should rounding leave `pick` just above 0
    pick -= weight;
    if (pick < 0) break;
  }
  if (!pointLightVisible(*lights[chosen], rays, x, n, raysCast)) return {};
  return shares[chosen] * (total / shares[chosen].luminance());
}

DirectLightStage::DirectLightStage(const Scene& scene, const PatchMesh& mesh, const RayCaster& rays,
                                   const SolveOptions& options, const ElementExposure* exposure,
                                   const std::vector<size_t>* lights)
    : scene_(scene),
      mesh_(mesh),
      rays_(rays),
      exposure_(exposure),
      seed_(options.seed),
      receiverPoints_(options.receiverPoints),
      keepPoints_(keepsPointValues(options)) {
  if (lights) {
    lights_ = *lights;
  } else {
    for (size_t l = 0; l < scene.lights.size(); ++l) lights_.push_back(l);
  }
  for (size_t l : lights_) {
    RAD_CHECK_LT(l, scene.lights.size());
    if (isPointLike(scene.lights[l])) pointLights_.push_back(&scene.lights[l]);
  }
  samplePointLights_ = pointLights_.size() > kEveryPointLight;
}

void DirectLightStage::compute(int e) {
  const Eigen::Vector3d n = mesh_.normal(e);
  const auto corners = mesh_.corners(e);
  const bool partlyBuried = exposure_ != nullptr && exposure_->buriedCells(e) != 0;
  uint64_t cast = 0;
  // The element's mean E_d, which the solver takes: stratified over its exposed area (the (s, t)
  // square maps onto the triangle preserving area, so its strata are equal areas of the element).
  // Not the receiver points: at three fixed interior points the light that pools along an
  // element's edges (under an arcade, beside a wall) is never seen; on the shared atrium that
  // made the indirectly lit parts 5-15% too dark at the default element size (docs/physics.md).
  const uint64_t stream = elementStream(mesh_, e);
  Rng jitter(streamKey(seed_ ^ stream_tag::kLightAreaMean, stream));
  Rgb areaSum;
  const int used =
      forEachExposedStratum(mesh_, exposure_, e, jitter, [&](const Eigen::Vector3d& x, int j) {
        for (size_t l : lights_) {
          if (samplePointLights_ && isPointLike(scene_.lights[l])) continue;
          areaSum += directIrradiance(
              scene_.lights[l], rays_, x, n,
              streamKey(seed_ ^ stream_tag::kLightAreaMean, stream, 1 + l * 64 + j), cast,
              kAreaRays);
        }
        if (samplePointLights_)
          areaSum += sampledPointLightIrradiance(pointLights_, rays_, x, n, jitter.uniform(), cast);
      });
  irradiance_[e] = areaSum / std::max(used, 1);
  elementRays_[e] = cast;
  if (!keepPoints_ && used > 0) return;
  // E_d at the receiver points: how the direct light varies inside the element, for the displayed
  // solution (addPointVariation); also the element's E_d where no stratum landed in its exposed
  // part (a sliver of it).
  auto points = receiverPoints(corners, receiverPoints_);
  const int count = receiverPoints_ == 1 ? 1 : 3;
  // Receiver points in a buried part of the element see no light, whatever reaches the rest.
  std::array<bool, 3> exposed{true, true, true};
  int exposedCount = count;
  if (partlyBuried) {
    exposedCount = 0;
    for (int k = 0; k < count; ++k) {
      const Eigen::Vector3d w =
          count == 1 ? Eigen::Vector3d::Constant(1.0 / 3) : receiverWeights(k);
      exposed[k] = !exposure_->buriedAtBarycentric(e, w[1], w[2]);
      exposedCount += exposed[k];
    }
    if (exposedCount == 0) {  // all of them buried: one exposed point instead
      const Eigen::Vector2d w = exposure_->exposedPoint(e);
      points[0] = corners[0] + w[0] * (corners[1] - corners[0]) + w[1] * (corners[2] - corners[0]);
      exposed[0] = true;
      exposedCount = 1;
    }
  }
  std::array<Rgb, 3> atPoints{};
  for (size_t l : lights_)
    for (int k = 0; k < count; ++k)
      if (exposed[k])
        atPoints[k] += directIrradiance(
            scene_.lights[l], rays_, points[k], n,
            streamKey(seed_ ^ stream_tag::kLightShot, stream, l * 3 + static_cast<uint64_t>(k)),
            cast);
  Rgb pointMean;
  for (int k = 0; k < count; ++k)
    if (exposed[k]) pointMean += atPoints[k];
  pointMean = pointMean / exposedCount;
  for (int k = 0; k < 3; ++k)
    if (k >= count || !exposed[k]) atPoints[k] = pointMean;
  if (keepPoints_) {
    pointIrradiance_[e] = atPoints;
    pointMean_[e] = pointMean;
  }
  if (used == 0) irradiance_[e] = pointMean;
  elementRays_[e] = cast;
}

void DirectLightStage::addEmission(RadiosityProblem& problem) const {
  for (int e = 0; e < mesh_.elementCount(); ++e)
    problem.emission[e] += problem.reflectance[e] * irradiance_[e];
}

void DirectLightStage::apply(RadiosityProblem& problem, const KnownIrradiance* known) {
  if (lights_.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  const int n = mesh_.elementCount();
  irradiance_.assign(n, Rgb());
  if (keepPoints_) {
    pointIrradiance_.assign(n, {});
    pointMean_.assign(n, Rgb());
  }
  elementRays_.assign(n, 0);
  int reused = 0;
  if (known) {
    RAD_CHECK_MSG(!keepPoints_, "known E_d has no receiver-point values");
    RAD_CHECK(known->value.size() == static_cast<size_t>(n) &&
              known->known.size() == static_cast<size_t>(n));
    reused = static_cast<int>(std::count(known->known.begin(), known->known.end(), 1));
  }
  tbb::parallel_for(0, n, [&](int e) {
    if (known && known->known[e])
      irradiance_[e] = known->value[e];
    else
      compute(e);
  });
  raysCast_ = std::accumulate(elementRays_.begin(), elementRays_.end(), uint64_t{0});
  addEmission(problem);
  if (std::all_of(irradiance_.begin(), irradiance_.end(), [](const Rgb& e) { return e.isZero(); }))
    logWarning(
        "the lights reach no surface from its front (all shadowed, behind or outside "
        "their cones): they add no light");
  const double seconds = secondsSince(start);
  logInfo("direct light: " + std::to_string(lights_.size()) + " light(s) at " + std::to_string(n) +
          " elements" +
          (known ? " (" + std::to_string(reused) + " kept from before the edit)" : std::string()) +
          ", " + std::to_string(raysCast_) + " shadow rays, " + formatNumber(seconds) + " s");
}

void DirectLightStage::meshChanged(const std::vector<int>& changed, RadiosityProblem& problem) {
  if (lights_.empty()) return;
  const int n = mesh_.elementCount();
  irradiance_.resize(n);
  if (keepPoints_) {
    pointIrradiance_.resize(n);
    pointMean_.resize(n);
  }
  elementRays_.resize(n, 0);
  tbb::parallel_for(size_t{0}, changed.size(), [&](size_t i) {
    const uint64_t before = elementRays_[changed[i]];
    compute(changed[i]);
    elementRays_[changed[i]] += before;  // keep counting the rays already cast
  });
  raysCast_ = std::accumulate(elementRays_.begin(), elementRays_.end(), uint64_t{0});
  addEmission(problem);
}

void DirectLightStage::addPointVariation(const RadiosityProblem& problem,
                                         std::vector<std::array<Rgb, 3>>& pointRadiosity) const {
  if (lights_.empty() || !keepPoints_ || pointRadiosity.size() != irradiance_.size()) return;
  for (size_t e = 0; e < pointRadiosity.size(); ++e)
    for (int k = 0; k < 3; ++k)
      pointRadiosity[e][k] += problem.reflectance[e] * (pointIrradiance_[e][k] - pointMean_[e]);
}

void DirectLightStage::report(SolveReport& report) const { report.directLightRays = raysCast_; }

}  // namespace rad
