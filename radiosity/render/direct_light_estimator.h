#pragma once

#include <Eigen/Core>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sampler.h"
#include "radiosity/render/scattering.h"
#include "radiosity/render/texel_footprint.h"

namespace rad {

// The variance of the mean of n samples of sum `sum` and sum of squares `squares`: s²/n, s² the
// unbiased sample variance (the second moment itself for a single sample).
Rgb varianceOfMean(const Rgb& sum, const Rgb& squares, int n);

// The direct light at a diffuse point by next-event estimation, as the eye passes over a
// radiosity solution that cast rays share it (DirectIndirectSplit, FinalGather): `lightRays`
// shadow rays to the emitters (EmitterSampler) and as many samples of each area light at
// infinity, the delta lights exactly (SceneLights), each in an MIS pair with the pass's cosine
// rays (`gathersPerLight` of them per shadow ray). For a lightmap texel the samples leave from
// points spread over its footprint; with a variance, each mean's s²/n is added to it (the
// texel's standard error).
class DirectLightEstimator {
 public:
  DirectLightEstimator(const RenderScene& scene, int lightRays, double gathersPerLight);

  // Multiple importance sampling (power heuristic, one light and one cosine sample per pair):
  // near corners the emitter-area estimator alone is heavy-tailed (cos·cos/d² grows without
  // bound), and the cosine-sampled rays cover exactly those directions well.
  static double misWeight(double pdfA, double pdfB);

  int lightRays() const { return lightRays_; }
  double gathersPerLight() const { return gathersPerLight_; }

  // ∫ L_e cos dω / π at `hit` (times ρ it is the reflected radiance). `variance`, when given,
  // gains the variance of each estimate's mean (s²/n per channel). `footprint`, when given,
  // spreads the samples' origins over it: the delta lights are then checked at about
  // lightRays / (their count) points of it instead of once at `hit`.
  Rgb directLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                  Rgb* variance = nullptr, const TexelFootprint* footprint = nullptr) const;
  // One shadow ray to the point `u` picks on the emitters: its irradiance / π, MIS-weighted
  // against a cosine-sampled ray. `gathersPerLight`: cosine rays per shadow ray in the MIS pair
  // (power heuristic with counts).
  Rgb lightSample(const SurfaceHit& hit, Point2 u, RayCounts& counts,
                  double gathersPerLight = 1.0) const;
  // `count` positions on hit's element spread over `footprint` (n-rooks stratified) into `out`;
  // none, and nothing drawn from `sampler`, when there is no footprint or it is a point.
  void spreadOrigins(const SurfaceHit& hit, const TexelFootprint* footprint, Sampler& sampler,
                     int count, std::vector<Eigen::Vector3d>& out) const;

  // The mean of along(from, direction) over `n` cosine-weighted directions about hit's normal
  // (the other half of the MIS pair), each from its own point of `footprint` when given;
  // `variance` as for directLight. Times ρ it is the reflected radiance.
  template <class Along>
  Rgb cosineMean(const SurfaceHit& hit, int n, Sampler& sampler, Rgb* variance,
                 const TexelFootprint* footprint, Along&& along) const {
    thread_local std::vector<Point2> points;
    thread_local std::vector<Eigen::Vector3d> origins;
    SurfaceHit at = hit;
    sampler.get2DArray(n, points);
    spreadOrigins(hit, footprint, sampler, n, origins);
    Rgb sum, squares;
    for (int k = 0; k < n; ++k) {
      if (!origins.empty()) at.position = origins[k];
      const Eigen::Vector3d d = cosineDirection(hit.normal, points[k].x, points[k].y);
      const Rgb v = along(static_cast<const SurfaceHit&>(at), d);
      sum += v;
      if (variance) squares += v * v;
    }
    if (variance) *variance += varianceOfMean(sum, squares, n);
    return sum / n;
  }

 private:
  // The scene lights' part of directLight (the point, spot, directional and sky lights).
  Rgb sceneLights(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts, Rgb* variance,
                  const TexelFootprint* footprint) const;

  const RenderScene& scene_;
  int lightRays_;
  double gathersPerLight_;
};

}  // namespace rad
