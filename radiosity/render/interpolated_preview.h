#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "meshing/vertex_interpolation.h"
#include "radiosity/render/integrator.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// The eye pass that reads a radiosity solution without casting rays at the diffuse hit
// (`--gather 0`): the interpolated B/π at the first diffuse hit, from the vertex values (the
// elements weighed by their exposed areas); at a hit in a buried cell of its element, which no
// light reaches, the emission alone (the ceiling above a panel hung just under it). Mirrors and
// glass continue the ray (DiffuseEyeHit), so they show the radiosity world, emitters included.
// Linear in B: the bounce terms' previews sum to the solution's.
class InterpolatedPreview : public SamplerIntegrator {
 public:
  // `radiosity`: B per element (W/m²); emission E = π·Ke comes from the materials.
  InterpolatedPreview(const RenderScene& scene, const std::vector<Rgb>& radiosity);

  using SamplerIntegrator::radiance;
  // The glass's Fresnel choices come from `sampler`.
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override;
  std::string name() const override { return "radiosity (interpolated, no gather)"; }

 private:
  Rgb interpolatedRadiance(const SurfaceHit& hit) const;  // B/π at the hit, from vertex values

  const RenderScene& scene_;
  ElementExposure exposure_;
  VertexInterpolation interpolation_;
  std::vector<Rgb> emitted_;                     // Le per element (its texture's average)
  std::vector<Eigen::Vector3d> vertexRadiance_;  // B/π per output vertex
  // H/π interpolated to the vertices (with textures): the albedo-free light that the texel's ρ
  // multiplies, smooth across elements of different mean reflectance.
  std::vector<Eigen::Vector3d> vertexIncident_;
};

}  // namespace rad
