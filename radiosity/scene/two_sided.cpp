#include "radiosity/scene/two_sided.h"

#include <algorithm>
#include <cstddef>

#include "radiosity/core/errors.h"

namespace rad {

void applyTwoSidedInput(Scene& scene, const TwoSidedInput& input) {
  for (const std::string& name : input.materials) {
    auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                           [&name](const Material& m) { return m.name == name; });
    if (it == scene.materials.end()) {
      std::string known;
      for (const Material& m : scene.materials) known += (known.empty() ? "" : ", ") + m.name;
      throw InputError(scene.sourcePath, 0,
                       "--two-sided-materials names '" + name +
                           "', which is not a material of this scene (its materials: " + known +
                           ")");
    }
    it->twoSided = true;
  }
  // --two-sided is for surfaces modelled facing the wrong way; an emitter keeps its one emitting
  // side (as Mitsuba's area lights, where `twosided` wraps only reflection) unless it is named.
  if (input.all)
    for (Material& m : scene.materials) m.twoSided = m.twoSided || !m.isEmitter();
}

int addBackSides(Scene& scene) {
  const std::size_t count = scene.polygons.size();
  std::vector<bool> hasBack(count, false);
  for (const ScenePolygon& p : scene.polygons)
    if (p.backSideOf >= 0) hasBack[static_cast<std::size_t>(p.backSideOf)] = true;
  int added = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const ScenePolygon& front = scene.polygons[i];
    const Material& material = scene.materials[static_cast<std::size_t>(front.material)];
    // Glass is seen from both sides already: its back is its inside, where refraction goes on.
    if (front.backSideOf >= 0 || hasBack[i] || !material.twoSided ||
        material.kind == SurfaceKind::Dielectric)
      continue;
    ScenePolygon back = front;
    back.backSideOf = static_cast<int>(i);
    // Reversed winding (the normal flips); per-corner data follows its corner.
    std::reverse(back.vertices.begin(), back.vertices.end());
    std::reverse(back.uvs.begin(), back.uvs.end());
    std::reverse(back.lightmapUvs.begin(), back.lightmapUvs.end());
    for (int& v : back.vertices) {
      scene.positions.push_back(scene.positions[static_cast<std::size_t>(v)]);
      v = static_cast<int>(scene.positions.size()) - 1;
    }
    scene.polygons.push_back(std::move(back));
    ++added;
  }
  return added;
}

}  // namespace rad
