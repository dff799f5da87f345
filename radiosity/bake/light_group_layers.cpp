#include "radiosity/bake/light_group_layers.h"

#include "radiosity/core/log.h"

namespace rad {

void reportLightGroups(const Solution& solution, BakeReport& report) {
  for (const LightLayer& layer : solution.layers) {
    BakeReport::Group group{layer.group, {}};
    for (int m : layer.group.materials)
      group.emissiveMaterials.push_back(solution.scene.materials[m].name);
    report.lightGroups.push_back(std::move(group));
  }
  if (!solution.layers.empty())
    logInfo("light groups: " + std::to_string(solution.layers.size()) +
            " layers (group_NAME_* files; they sum to the whole)");
}

std::vector<std::vector<Lightmap>> lightGroupPages(
    const Solution& solution, LightmapPages& pages,
    const std::vector<std::vector<Rgb>>& layerVertexValues, const std::vector<Rgb>& elementEmission,
    const std::vector<Lightmap>& whole) {
  const PatchMesh& mesh = *solution.mesh;
  std::vector<std::vector<Lightmap>> layers;
  for (size_t g = 0; g < solution.layers.size(); ++g) {
    const LightGroup& group = solution.layers[g].group;
    std::vector<char> member(solution.scene.materials.size(), 0);
    for (int m : group.materials) member[m] = 1;
    std::vector<Rgb> groupLe(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e)
      if (member[mesh.material(e)]) groupLe[e] = elementEmission[e];
    layers.push_back(
        pages.bake({solution.layers[g].radiosity, layerVertexValues[g], groupLe}, &whole));
  }
  return layers;
}

}  // namespace rad
