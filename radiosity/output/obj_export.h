#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "radiosity/output/lightmap_baked_mesh.h"

namespace rad {

// Writes the baked mesh as Wavefront OBJ + MTL with the lightmap UVs as `vt` (v up, as OBJ
// expects: v = 1 − glTF v). Each scene material becomes an MTL material that shows the
// lightmap unlit: `illum 0` (colour = Kd, no lighting) with Kd 1 and `map_Kd` = `texture`
// (a file name relative to the MTL) of its lightmap page: `pageTextures` has one per page, and
// with several pages each scene material becomes one MTL material per page it appears on
// (`NAME_pageP`). `mtlName` is the MTL's file name as the OBJ references it.
// The mesh must have lightmap UVs (RAD_CHECK: CheckFailure otherwise).
void writeBakedObj(std::ostream& obj, std::ostream& mtl, const BakedMesh& mesh,
                   const std::string& mtlName, const std::vector<std::string>& pageTextures);

}  // namespace rad
