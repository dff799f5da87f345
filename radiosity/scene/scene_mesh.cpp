#include "radiosity/scene/scene_mesh.h"

namespace rad {

PatchMesh buildPatchMesh(const Scene& scene) {
  // The mesh carries UVs only when every polygon has them (the lightmap's use of scene UVs
  // requires that, and reports the faces without).
  const bool uvs =
      !scene.polygons.empty() && scene.polygonsWithUvs() == static_cast<int>(scene.polygons.size());
  std::vector<PatchPolygon> polygons;
  polygons.reserve(scene.polygons.size());
  for (const ScenePolygon& p : scene.polygons)
    polygons.push_back({p.vertices, p.material, uvs ? p.uvs : std::vector<Eigen::Vector2d>{}});
  return PatchMesh(scene.positions, polygons);
}

}  // namespace rad
