#pragma once

#include "meshing/patch_mesh.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The coordinates a lightmap bakes into (bake --use-scene-uvs, the PatchMesh's UVs): the
// polygon's lightmap set (glTF's TEXCOORD_1) when it has one, else its texture coordinates.
inline const std::vector<Eigen::Vector2d>& bakeUvs(const ScenePolygon& polygon) {
  return polygon.lightmapUvs.empty() ? polygon.uvs : polygon.lightmapUvs;
}

// The scene's polygons as patches of a PatchMesh (one patch per polygon, same material index),
// with the texture coordinates of each polygon that has them.
PatchMesh buildPatchMesh(const Scene& scene);

}  // namespace rad
