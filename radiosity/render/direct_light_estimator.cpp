#include "radiosity/render/direct_light_estimator.h"

#include <algorithm>
#include <cmath>

#include "radiosity/render/scene_lights.h"

namespace rad {

Rgb varianceOfMean(const Rgb& sum, const Rgb& squares, int n) {
  Rgb v;
  if (n <= 0) return v;
  for (int c = 0; c < 3; ++c) {
    const double spread = squares[c] - sum[c] * sum[c] / n;
    v[c] = n > 1 ? std::max(0.0, spread) / (double(n) * (n - 1)) : squares[c];
  }
  return v;
}

double DirectLightEstimator::misWeight(double pdfA, double pdfB) {
  const double a = pdfA * pdfA, b = pdfB * pdfB;
  return a / (a + b);
}

DirectLightEstimator::DirectLightEstimator(const RenderScene& scene, int lightRays,
                                           double gathersPerLight)
    : scene_(scene), lightRays_(lightRays), gathersPerLight_(gathersPerLight) {}

Rgb DirectLightEstimator::lightSample(const SurfaceHit& hit, Point2 u, RayCounts& counts,
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

void DirectLightEstimator::spreadOrigins(const SurfaceHit& hit, const TexelFootprint* footprint,
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

Rgb DirectLightEstimator::directLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                                      Rgb* variance, const TexelFootprint* footprint) const {
  thread_local std::vector<Point2> points;
  thread_local std::vector<Eigen::Vector3d> origins;
  SurfaceHit at = hit;  // where each sample leaves from: hit, or its own point of the footprint
  const int n = lightRays_;
  sampler.get2DArray(n, points);
  spreadOrigins(hit, footprint, sampler, n, origins);
  Rgb sum, squares;
  for (int k = 0; k < n; ++k) {
    if (!origins.empty()) at.position = origins[k];
    const Rgb v = lightSample(at, points[k], counts, gathersPerLight_);
    sum += v;
    if (variance) squares += v * v;
  }
  if (variance) *variance += varianceOfMean(sum, squares, n);
  sum = sum / n;
  if (scene_.lights().empty()) return sum;  // irradiance / π: times ρ it is the reflected radiance
  return sum + sceneLights(hit, sampler, counts, variance, footprint);
}

Rgb DirectLightEstimator::sceneLights(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                                      Rgb* variance, const TexelFootprint* footprint) const {
  // The point, spot, directional and sky lights: the delta ones once (exact) at one point, at
  // about n / (their count) points over a footprint (so about n shadow rays in all); the sun's
  // disc and the sky by n samples each, stratified, in the same MIS pair with the cosine rays.
  thread_local std::vector<Point2> points;
  thread_local std::vector<Eigen::Vector3d> origins;
  SurfaceHit at = hit;
  const int n = lightRays_;
  const SceneLights& lights = scene_.lights();
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
      const Rgb v = lights.sampleArea(a, scene_, at, points[k], counts, gathersPerLight_);
      area += v;
      if (variance) areaSquares += v * v;
    }
    if (variance) *variance += varianceOfMean(area, areaSquares, n) / (M_PI * M_PI);
    fromLights += area / n;
  }
  return fromLights / M_PI;
}

}  // namespace rad
