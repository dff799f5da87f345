#include "radiosity/scene/scene.h"

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

}  // namespace rad
