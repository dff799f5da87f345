#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radiosity/render/direct_light_estimator.h"
#include "radiosity/render/element_solution.h"
#include "radiosity/render/final_gather_options.h"
#include "radiosity/render/integrator.h"
#include "radiosity/render/texel_radiance.h"

namespace rad {

// The final gather over a radiosity solution (B per element, stored on the mesh; `--gather N`,
// N > 0): L(D|S)*E from the camera, at the first diffuse hit the direct light by shadow rays
// (DirectLightEstimator) plus N cosine-weighted gather rays into the solution's reflected part
// (B − E)/π, the two sharing the direct light by MIS (FinalGatherOptions). Mirrors and glass
// continue the eye ray (DiffuseEyeHit), so they show the radiosity world, emitters included.
class FinalGather : public SamplerIntegrator, public TexelRadiance {
 public:
  // `radiosity`: B per element (W/m²); emission E = π·Ke comes from the materials.
  // `options.gatherRays` > 0.
  FinalGather(const RenderScene& scene, const std::vector<Rgb>& radiosity,
              FinalGatherOptions options);

  using SamplerIntegrator::radiance;
  // Shadow-ray points and gather directions come from `sampler` (stratified across the pixel).
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override;
  std::string name() const override;

  // For baking lightmaps by per-texel final gather: Ke + ρ·(direct + gathered light).
  using TexelRadiance::outgoingRadiance;
  Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                       RayCounts& counts, Rgb& standardError) const override;

 private:
  // The mean incoming radiance along the gather rays: the solution's reflected light, the
  // shadow rays' MIS pair.
  Rgb gatherLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                  Rgb* variance = nullptr, const TexelFootprint* footprint = nullptr) const;
  // Per element: the mean of lightSample over its area (stratified points), and whether every
  // one of those points saw the emitters alike (all lit, or none: no shadow edge, no emitter
  // plane crossing the element). The means are over the elements' exposed points.
  struct ElementLight {
    std::vector<Rgb> mean;
    std::vector<char> uniform;
  };
  ElementLight meanLightSample(const ElementExposure& exposure) const;
  // Incoming radiance along a gather ray leaving `from`; `mayContinue`: a landing too close
  // gathers once more (the continuation itself reads the solution wherever it lands).
  Rgb secondaryRadiance(const SurfaceHit& from, Eigen::Vector3d direction, Rng& rng,
                        RayCounts& counts, bool mayContinue) const;
  // The gather ray's landing on a diffuse element, directly from `from` (not through mirrors).
  Rgb landing(const SurfaceHit& from, const SurfaceHit& hit, const Eigen::Vector3d& direction,
              Rng& rng, RayCounts& counts, bool mayContinue) const;

  const RenderScene& scene_;
  int gatherRays_;
  DirectLightEstimator direct_;
  ElementSolution solution_;
  // (B − E)/π − ρ·(the element's mean of lightSample) per element: the solution's reflected
  // light less its shadow-ray share, which a gather ray's landing point takes at the point.
  std::vector<Rgb> indirect_;
  // Per element: its points all saw the emitters alike, so a landing there takes the element's
  // mean shadow-ray share instead of casting its own shadow ray.
  std::vector<char> uniformLight_;
  std::vector<double> elementSize_;  // √area per element: a gather ray landing closer continues
};

}  // namespace rad
