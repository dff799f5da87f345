#pragma once

#include <memory>
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/bake/bake_rays.h"
#include "radiosity/bake/bake_spec.h"
#include "radiosity/bake/texel_evaluation.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/render/integrator.h"
#include "radiosity/render/texel_radiance.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// The lightmap pages of a solution on a layout, rasterised and dilated (bakeLightmap), each
// texel by the evaluator the spec chooses: the per-texel gather with --gather or --light-rays,
// else the interpolated solution (texel_evaluation.h).
class LightmapPages {
 public:
  // The gather's view of the scene comes from `rays` (built there when a gather needs it).
  LightmapPages(const Solution& solution, const LightmapLayout& layout,
                const VertexInterpolation& interpolation, const ElementExposure& exposure,
                const BakeSpec& spec, BakeRays& rays);

  bool gathered() const { return gather_ != nullptr; }

  // One page per layout page of `values`. With `shape` (the whole's pages), the pages are made on
  // its texels (bakeOnTexels) instead of rasterised again: a light group's layer. The gather
  // rasterises every page (the command refuses it for light groups).
  std::vector<Lightmap> bake(const TexelSolution& values,
                             const std::vector<Lightmap>* shape = nullptr);

  // Per page and texel, the gather's standard error of the pages last baked; empty without a
  // gather.
  const std::vector<std::vector<Rgb>>& gatherError() const { return gatherError_; }

 private:
  const Solution& solution_;
  const LightmapLayout& layout_;
  const VertexInterpolation& interpolation_;
  const ElementExposure& exposure_;
  const BakeSpec& spec_;
  // The pass over the solution that casts rays per texel (makeRadiosityIntegrator), and it as a
  // TexelRadiance; none without a gather.
  std::unique_ptr<const Integrator> gatherPass_;
  const TexelRadiance* gather_ = nullptr;
  std::vector<std::vector<Rgb>> gatherError_;
};

}  // namespace rad
