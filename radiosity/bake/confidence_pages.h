#pragma once

// The confidence map of a bake (docs/baking.md, "How far to trust each texel"): the lightmap's
// "error" EXR channel and bake.json's `confidence`.
#include <vector>

#include "meshing/lightmap_packing.h"
#include "radiosity/bake/bake_report.h"
#include "radiosity/bake/bake_spec.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// Per page of `lightmaps`, the estimated absolute error of each texel's value per channel
// (W·m⁻²·sr⁻¹), on the same texels and dilated like the values. Without a gather (`gatherError`
// empty): the mesh's displayed error (displayedError, the refinement's estimate) of what the
// texel interpolates, scaled as InterpolatedTexels forms the value: the radiance's own; the light
// arriving (H/π) times the texel's ρ where a texture multiplies it; H/π's alone for irradiance
// content; 0 where the texel is buried (its value, the emission alone, is exact). With a gather:
// its standard error (per page and texel; ÷ ρ for irradiance content). The gather reads the
// solution one bounce away, averaged over many elements, so the mesh's displayed error does not
// apply there. Left out: the solution's own error (its form-factor rays' noise, its elements'
// means) where it reaches the texel through the gathered light, or through the interpolated
// values.
std::vector<Lightmap> confidencePages(const Solution& solution, const LightmapLayout& layout,
                                      const std::vector<Lightmap>& lightmaps,
                                      LightmapContent content,
                                      const std::vector<std::vector<Rgb>>& gatherError,
                                      const ElementExposure& exposure);

// The bake's step: confidencePages, their summary over the covered texels in
// `report.confidence` (with which errors it includes), and the log line.
std::vector<Lightmap> bakeConfidence(const Solution& solution, const LightmapLayout& layout,
                                     const std::vector<Lightmap>& lightmaps, const BakeSpec& spec,
                                     const std::vector<std::vector<Rgb>>& gatherError,
                                     const ElementExposure& exposure, BakeReport& report);

}  // namespace rad
