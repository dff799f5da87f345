#pragma once

#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/bake/bake_report.h"
#include "radiosity/bake/bake_spec.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/render/directional_lightmap.h"
#include "radiosity/render/render_scene.h"

namespace rad {

// --directional: per page of `layout`, the L1 SH of the incident radiance at each texel
// (render/directional_lightmap), spec.directionalRays rays per texel from the spec's seed;
// `report.directional` says how many and how long.
std::vector<DirectionalLightmapPage> bakeDirectionalPages(const RenderScene& view,
                                                          const Solution& solution,
                                                          const LightmapLayout& layout,
                                                          const VertexInterpolation& interpolation,
                                                          const BakeSpec& spec, BakeReport& report);

}  // namespace rad
