#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "meshing/vertex_interpolation.h"
#include "radiosity/render/direct_light_estimator.h"
#include "radiosity/render/integrator.h"
#include "radiosity/render/texel_radiance.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// The eye pass over a radiosity solution that splits the light at the first diffuse hit
// (`--gather 0 --light-rays N`): the direct light by its own N shadow rays (a shadow's edge, a
// light's fall-off, exact however coarse the mesh; DirectLightEstimator, in an MIS pair with N
// cosine rays that only look for the lights), the interreflected light from the solution,
// interpolated: no gather ray, so no gather noise; the indirect part's discretisation is the bias,
// small where the indirect light varies slowly (docs/rendering.md). Mirrors and glass continue the
// eye ray (DiffuseEyeHit).
class DirectIndirectSplit : public SamplerIntegrator, public TexelRadiance {
 public:
  // `radiosity`: B per element (W/m²); emission E = π·Ke comes from the materials;
  // `directIrradiance`: E_d per element as the solve computed it (Solution::directIrradiance).
  DirectIndirectSplit(const RenderScene& scene, const std::vector<Rgb>& radiosity,
                      const std::vector<Rgb>& directIrradiance, int lightRays);

  using SamplerIntegrator::radiance;
  // Shadow-ray points and cosine directions come from `sampler` (stratified across the pixel).
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override;
  std::string name() const override;

  // Ke + ρ·(direct + the interpolated indirect light); a buried point takes no indirect light.
  using TexelRadiance::outgoingRadiance;
  Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                       RayCounts& counts, Rgb& standardError) const override;

 private:
  // The solution's indirect incident light H_i/π at barycentrics (u, v) of `element`, from
  // vertexIndirect_.
  Rgb interpolatedIndirect(int element, double u, double v) const;
  // The mean over the cosine rays of what they find of the lights straight ahead (lightAlong).
  Rgb lightsAlong(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                  Rgb* variance = nullptr, const TexelFootprint* footprint = nullptr) const;
  // What a cosine-sampled ray from `from` finds of the lights straight ahead (an emitter, the
  // sky), MIS-weighted against one shadow ray per cosine ray.
  Rgb lightAlong(const SurfaceHit& from, const Eigen::Vector3d& direction, RayCounts& counts) const;

  const RenderScene& scene_;
  DirectLightEstimator direct_;
  // The buried parts of the elements (element_exposure.h): the mean light of an element is over
  // its exposed points, and vertex values weigh elements by their exposed areas.
  ElementExposure exposure_;
  VertexInterpolation interpolation_;
  // Per output vertex, the solution's reflected light less its direct part, divided by ρ: the
  // albedo-free indirect light H_i/π that the point's ρ multiplies.
  std::vector<Eigen::Vector3d> vertexIndirect_;
};

}  // namespace rad
