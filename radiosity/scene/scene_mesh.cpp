#include "radiosity/scene/scene_mesh.h"

namespace rad {

PatchMesh buildPatchMesh(const Scene& scene) {
  // The mesh carries the lightmap's UVs (bakeUvs) only when every polygon has
  // them (the lightmap's use of scene UVs requires that, and reports the faces without).
  bool uvs = !scene.polygons.empty();
  for (const ScenePolygon& p : scene.polygons) uvs = uvs && !bakeUvs(p).empty();
  std::vector<PatchPolygon> polygons;
  polygons.reserve(scene.polygons.size());
  for (const ScenePolygon& p : scene.polygons)
    polygons.push_back({p.vertices, p.material, uvs ? bakeUvs(p) : std::vector<Eigen::Vector2d>{}});
  return PatchMesh(scene.positions, polygons);
}

}  // namespace rad
