#pragma once

#include <Eigen/Core>
#include <vector>

#include "radiosity/scene/scene.h"

namespace rad::testing {

// A scene with no geometry yet, one grey Lambertian material (index 0) of reflectance `rho`, and
// `lights`: the start of the small analytic scenes the tests build by hand.
inline Scene greyScene(const Rgb& rho, const std::vector<Light>& lights = {}) {
  Scene scene;
  scene.sourcePath = "test";
  Material grey;
  grey.name = "grey";
  grey.diffuse = rho;
  scene.materials.push_back(grey);
  scene.lights = lights;
  return scene;
}

// Adds a one-sided polygon (corners counter-clockwise seen from the front) of `material`.
inline void addPolygon(Scene& scene, const std::vector<Eigen::Vector3d>& corners,
                       int material = 0) {
  ScenePolygon polygon;
  for (const auto& c : corners) {
    polygon.vertices.push_back(static_cast<int>(scene.positions.size()));
    scene.positions.push_back(c);
  }
  polygon.material = material;
  scene.polygons.push_back(polygon);
}

}  // namespace rad::testing
