#pragma once

#include "meshing/lightmap_packing.h"
#include "meshing/patch_mesh.h"

namespace rad {

// A lightmap layout in the mesh's own UVs (PatchMesh::hasUvs), for scenes that bring their
// lightmap UVs. Charts are the UV islands: elements joined across mesh edges whose two ends have
// the same UVs on both sides (and all elements of one input polygon). Texel coordinates are the
// UVs scaled to width × height with v flipped, so row 0 is the top as in glTF, and the winding
// seen with v up is kept. rects are the islands' bounding boxes in texels, which may overlap when
// islands interleave; layout.padding is the dilation limit the caller allows. The UVs must have
// passed checkLightmapUvs (in [0, 1], non-degenerate, no overlaps): this only lays them out.
LightmapLayout layoutFromMeshUvs(const PatchMesh& mesh, int width, int height, int padding);

// The square atlas side whose texels measure about `texelSize` scene units on average over the
// surface (sqrt of surface area over UV area); throws InputError above maxSide.
int atlasSideForTexelSize(const PatchMesh& mesh, double texelSize, int maxSide);

}  // namespace rad
