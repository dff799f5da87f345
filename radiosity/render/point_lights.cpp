#include "radiosity/render/point_lights.h"

#include <map>

namespace rad {

std::vector<PointLight> emitterPointLights(const RenderScene& scene) {
  const PatchMesh& mesh = scene.mesh();
  std::map<int, PointLight> byPatch;  // ordered: the same lights in the same order every run
  std::map<int, Eigen::Vector3d> weightedNormal;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Material& m = scene.material(e);
    if (!m.isEmitter()) continue;
    const int patch = mesh.patch(e);
    PointLight& light = byPatch[patch];
    if (light.patch < 0) {
      light.patch = patch;
      light.radiance = m.emission;
      light.position = Eigen::Vector3d::Zero();
      weightedNormal[patch] = Eigen::Vector3d::Zero();
    }
    const auto c = mesh.corners(e);
    const double a = mesh.area(e);
    light.area += a;
    light.position += a * (c[0] + c[1] + c[2]) / 3.0;
    weightedNormal[patch] += a * mesh.normal(e);
  }
  std::vector<PointLight> lights;
  for (auto& [patch, light] : byPatch) {
    light.position /= light.area;
    light.normal = weightedNormal[patch].normalized();
    lights.push_back(light);
  }
  return lights;
}

}  // namespace rad
