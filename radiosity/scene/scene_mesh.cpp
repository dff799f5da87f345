#include "radiosity/scene/scene_mesh.h"

namespace rad {

PatchMesh buildPatchMesh(const Scene& scene) {
  // Every polygon's texture coordinates go to its elements, for texture look-ups, and its lightmap
  // set (bakeUvs) beside them; a lightmap in the scene's UVs needs that set on every element
  // (PatchMesh::hasLightmapUvs) and reports the faces without.
  std::vector<PatchPolygon> polygons;
  polygons.reserve(scene.polygons.size());
  for (const ScenePolygon& p : scene.polygons)
    polygons.push_back({p.vertices, p.material, p.uvs, p.lightmapUvs});
  return PatchMesh(scene.positions, polygons);
}

}  // namespace rad
