#include "radiosity/scene/scene_mesh.h"

namespace rad {

PatchMesh buildPatchMesh(const Scene& scene) {
  std::vector<PatchPolygon> polygons;
  polygons.reserve(scene.polygons.size());
  for (const ScenePolygon& p : scene.polygons) polygons.push_back({p.vertices, p.material});
  return PatchMesh(scene.positions, polygons);
}

}  // namespace rad
