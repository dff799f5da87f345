#pragma once

#include <Eigen/Core>

#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sampler.h"
#include "radiosity/render/texel_footprint.h"

namespace rad {

// The outgoing radiance at a point of a diffuse element seen from its front, estimated by rays
// cast from there: what a lightmap bake asks of the eye passes that cast rays (DirectIndirectSplit,
// FinalGather) per texel (bake/texel_evaluation.h). Mirrors and glass hold no radiance of their
// own here: 0; an element that reflects nothing: its Ke.
class TexelRadiance {
 public:
  virtual ~TexelRadiance() = default;

  // The estimate over a lightmap texel's footprint on `element`, its points drawn from `sampler`
  // (a texel's SobolSampler: its N rays of each kind one stratified set): every shadow and cosine
  // ray (and each delta light's share of them) leaves from its own point, stratified over the
  // texel, so the value is the texel's box-filtered mean, not its centre's (a shadow edge or the
  // light's fall-off inside the texel averaged as Cycles' bake averages them). ρ is the centre's.
  // A footprint that is a point gives the value at its centre. `standardError`: per channel the
  // standard error of that Monte Carlo estimate, ρ·√(Σ s²/n) over its means (the shadow rays',
  // each area light's, the cosine rays'), s² the sample variance of the n samples of each. The
  // samples are taken as independent; their stratification can only lower the true error below
  // this (up to a factor √(n/(n−1)) for n-rooks points). 0 where nothing is sampled (a delta light
  // alone, ρ = 0).
  virtual Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                               RayCounts& counts, Rgb& standardError) const = 0;

  // The same with independent points from `rng` (bit for bit as a RandomSampler on it).
  Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Rng& rng, RayCounts& counts,
                       Rgb& standardError) const;
  // At one point (barycentrics over the element's corners): the footprint that is that point.
  Rgb outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng, RayCounts& counts,
                       Rgb& standardError) const;
  // The same value (bit for bit, from the same rng) without its standard error.
  Rgb outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                       RayCounts& counts) const;
};

// The front of `element` at `barycentric` as a hit of the eye passes: position, normal, the
// reflectance there (the texture's texel), material.
SurfaceHit texelHit(const RenderScene& scene, int element, const Eigen::Vector3d& barycentric);

}  // namespace rad
