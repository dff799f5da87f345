#pragma once

// What one texel of a lightmap page holds (--lightmap-content; docs/baking.md), by one of two
// evaluators: the solution interpolated inside its element, or a final gather per texel.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/rgb.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/render/texel_radiance.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// Whether texels are made of the light arriving (H/π at the vertices) rather than of the
// interpolated radiance alone: for irradiance content, and in a scene with textures, whose
// textured elements show at each texel their own texel of the texture times the smooth light
// arriving (the others keep the interpolated radiance).
bool texelsFromIncidentLight(const Scene& scene, LightmapContent content);

// The solution one set of pages is made of: the whole, or one light group's layer with its own
// emitters' Le. Every evaluator is linear in B and Le, so the layers' pages add up to the whole's.
struct TexelSolution {
  const std::vector<Rgb>& radiosity;     // B per element
  const std::vector<Rgb>& vertexValues;  // B/π at the interpolation's vertices
  const std::vector<Rgb>& emission;      // Le per element
};

// The interpolated solution, with the texture's detail inside each element (or without the
// albedo at all); where the point is buried (no light arrives there: the floor under a box
// standing on it, the ceiling behind a one-sided lamp), what it emits alone. Measured on the
// Cornell box, 3.3% of the texels are buried; interpolating the element's exposed part over them
// made the lightmap 1.55% brighter than Cycles' bake.
class InterpolatedTexels {
 public:
  InterpolatedTexels(const Solution& solution, const VertexInterpolation& interpolation,
                     const ElementExposure& exposure, LightmapContent content,
                     const TexelSolution& values);

  Rgb operator()(int element, const Eigen::Vector3d& barycentric) const;

 private:
  const Scene& scene_;
  const PatchMesh& mesh_;
  const VertexInterpolation& interpolation_;
  const ElementExposure& exposure_;
  const std::vector<Rgb>& vertexValues_;
  const std::vector<Rgb>& emission_;
  bool irradiance_, textured_;
  // H/π at the vertices: the light arriving, smooth across elements of different reflectance.
  std::vector<Rgb> vertexIncident_;
};

// Per-texel final gather (--gather N, or --gather 0 --light-rays N: any TexelRadiance, from
// makeRadiosityIntegrator): direct light by shadow rays to the emitters at every texel and the
// light from the solution (gathered, or its indirect part interpolated), for
// shadows sharper than the elements. The rays leave from points spread over the texel's
// footprint on its element: the texel holds its box-filtered mean, as Cycles' bake and the
// engines' lightmappers give. Each texel draws from its own stream, streamKey(seed,
// stream_tag::kLightmapTexel + page, texel), so a page is the same for a seed whatever the thread
// count.
class GatheredTexels {
 public:
  GatheredTexels(const Solution& solution, const TexelRadiance& gather,
                 const LightmapLayout& layout, LightmapContent content, uint64_t seed);

  // The texel's value, and the Monte Carlo standard error of it (for the confidence map).
  Rgb operator()(int page, int element, const Eigen::Vector3d& barycentric, size_t texel,
                 Rgb& standardError) const;

 private:
  const Scene& scene_;
  const PatchMesh& mesh_;
  const TexelRadiance& gather_;
  const LightmapLayout& layout_;
  bool irradiance_;
  uint64_t seed_;
};

}  // namespace rad
