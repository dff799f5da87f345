#pragma once

#include "meshing/patch_mesh.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The scene's polygons as patches of a PatchMesh (one patch per polygon, same material index),
// with the texture coordinates of each polygon that has them.
PatchMesh buildPatchMesh(const Scene& scene);

}  // namespace rad
