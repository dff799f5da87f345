#include "radiosity/pipeline/direct_light_stage.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "meshing/element_stream.h"
#include "radiosity/core/check.h"
#include "radiosity/core/hemisphere.h"
#include "radiosity/core/log.h"
#include "radiosity/core/rng.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/formfactors/receiver_points.h"
#include "radiosity/lighting/light_choice.h"
#include "radiosity/lighting/light_sample.h"
#include "radiosity/pipeline/solver_results.h"

namespace rad {
namespace {

// Whether the shadow ray from x (normal n) along the sample's direction reaches the light.
bool reaches(const LightSample& sample, const RayCaster& rays, const Eigen::Vector3d& x,
             const Eigen::Vector3d& n, uint64_t& raysCast) {
  ++raysCast;
  const Eigen::Vector3d origin = rays.liftOff(x, n, sample.direction);
  if (!std::isfinite(sample.distance))
    return !rays.occluded(origin, sample.direction, std::numeric_limits<double>::infinity());
  const Eigen::Vector3d target = x + sample.direction * sample.distance;
  return !rays.occluded(origin, target - origin, 1.0 - 1e-6);
}

// The mean, over m² samples of the light stratified over the unit square, of their irradiance
// where their shadow ray is clear: a sun's disc, a sky sampled about the normal.
Rgb byLightSamples(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                   const Eigen::Vector3d& n, int m, Rng& rng, uint64_t& raysCast) {
  Rgb sum;
  const int count = m * m;
  for (int k = 0; k < count; ++k) {
    const double u1 = (k % m + rng.uniform()) / m, u2 = (k / m + rng.uniform()) / m;
    const LightSample s = sampleLight(light, x, n, u1, u2);
    if (s.found() && reaches(s, rays, x, n, raysCast)) sum += s.irradiance;
  }
  return sum / count;
}

// A light sampled by its map (an environment, a clear sky): half the rays by the map's luminance,
// half cosine-weighted, each stratified (m × m / 2) and combined by the balance heuristic, so a
// sun in the image is found and a dim, wide map stays smooth: E = Σ L cosθ / (n (p_map + p_cos))
// over both sets' unshadowed rays, n rays in each.
Rgb byMapAndCosine(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                   const Eigen::Vector3d& n, int m, Rng& rng, uint64_t& raysCast) {
  const Frame frame(n);
  const int kEach = m * m / 2;
  Rgb sum;
  for (int k = 0; k < 2 * kEach; ++k) {
    const int s = k % kEach;
    const double u1 = (s % m + rng.uniform()) / m, u2 = (s / m + rng.uniform()) / (m / 2);
    LightSample sample;
    if (k < kEach) {
      sample = sampleLight(light, x, n, u1, u2);
    } else {
      sample.direction = frame.toWorld(cosineWeightedDirection(u1, u2));
      sample.cosTheta = n.dot(sample.direction);
      sample.radiance = radianceAlong(light, sample.direction);
    }
    if (!(sample.cosTheta > 0) || sample.radiance.isZero()) continue;
    if (!reaches(sample, rays, x, n, raysCast)) continue;
    sum += sample.radiance *
           (sample.cosTheta / (lightPdf(light, n, sample.direction) + sample.cosTheta / M_PI));
  }
  return sum / kEach;
}

bool isPointOrSpot(const Light& light) {
  return light.type == LightType::Point || light.type == LightType::Spot;
}

}  // namespace

Rgb directIrradiance(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                     const Eigen::Vector3d& n, uint64_t key, uint64_t& raysCast,
                     const DirectRays& count) {
  if (isDeltaLight(light)) {
    const LightSample s = sampleLight(light, x, n, 0, 0);
    return s.found() && reaches(s, rays, x, n, raysCast) ? s.irradiance : Rgb();
  }
  Rng rng(key);
  if (light.map) return byMapAndCosine(light, rays, x, n, count.skyStrata, rng, raysCast);
  const int m = light.type == LightType::Directional ? count.sunStrata : count.skyStrata;
  return byLightSamples(light, rays, x, n, m, rng, raysCast);
}

Rgb sampledPointLightIrradiance(const std::vector<const Light*>& lights, const RayCaster& rays,
                                const Eigen::Vector3d& x, const Eigen::Vector3d& n, double u,
                                uint64_t& raysCast) {
  const LightChoice choice = chooseLight(lights, x, n, u);
  if (!choice.sample.found() || !reaches(choice.sample, rays, x, n, raysCast)) return {};
  return choice.sample.irradiance * choice.weight;
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
    if (isPointOrSpot(scene.lights[l])) pointLights_.push_back(&scene.lights[l]);
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
          if (samplePointLights_ && isPointOrSpot(scene_.lights[l])) continue;
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
