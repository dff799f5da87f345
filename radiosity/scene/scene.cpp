#include "radiosity/scene/scene.h"

#include "radiosity/core/errors.h"

namespace rad {

int Scene::emitterCount() const {
  int count = 0;
  for (const ScenePolygon& polygon : polygons) {
    if (materials[polygon.material].isEmitter()) ++count;
  }
  return count;
}

bool Scene::hasSpecular() const {
  for (const ScenePolygon& polygon : polygons) {
    if (materials[polygon.material].isSpecular()) return true;
  }
  return false;
}

int Scene::polygonsWithUvs() const {
  int count = 0;
  for (const ScenePolygon& polygon : polygons) count += !polygon.uvs.empty();
  return count;
}

int Scene::backSideCount() const {
  int count = 0;
  for (const ScenePolygon& polygon : polygons) count += polygon.backSideOf >= 0;
  return count;
}

void requireEmitter(const Scene& scene) {
  if (scene.emitterCount() > 0 || !scene.lights.empty()) return;
  throw InputError(scene.sourcePath, 0,
                   "no emitter: no polygon uses a material with positive Ke and there is no "
                   "light (--lights, --sky, --sun, or a .lights.json beside the scene), so the "
                   "scene would stay dark");
}

}  // namespace rad
