#pragma once

// --light-groups: each group's layer of the bake, beside the whole's (pipeline/light_group_solve
// solves them; their sum is the solution).
#include <vector>

#include "radiosity/bake/bake_report.h"
#include "radiosity/bake/lightmap_pages.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/pipeline/solution.h"

namespace rad {

// The groups of the solution's layers, with their emissive materials' names, in
// `report.lightGroups`; logs them.
void reportLightGroups(const Solution& solution, BakeReport& report);

// Per layer of the solution, its lightmap pages on the texels of the whole's (`whole`): its B,
// its vertex values (`layerVertexValues`, per layer) and the emission of its own emitters alone
// (of `elementEmission`, the whole's Le per element). Each texel is linear in B and Le, so the
// layers' pages sum to the whole's.
std::vector<std::vector<Lightmap>> lightGroupPages(
    const Solution& solution, LightmapPages& pages,
    const std::vector<std::vector<Rgb>>& layerVertexValues, const std::vector<Rgb>& elementEmission,
    const std::vector<Lightmap>& whole);

}  // namespace rad
