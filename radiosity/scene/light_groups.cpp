#include "radiosity/scene/light_groups.h"

#include <map>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

std::string safeFileName(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '-';
    if (!keep) c = '_';
  }
  // "." and ".." are directories, not file names.
  if (out.find_first_not_of('.') == std::string::npos) out = std::string(out.size(), '_');
  return out;
}

}  // namespace

std::vector<LightGroup> lightGroups(const Scene& scene) {
  std::vector<LightGroup> groups;
  std::map<std::string, size_t> byName;
  auto groupNamed = [&](const std::string& name) -> LightGroup& {
    auto [it, added] = byName.emplace(name, groups.size());
    if (added) groups.push_back({name, safeFileName(name), {}, {}});
    return groups[it->second];
  };
  for (size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].isEmitter())
      groupNamed(scene.materials[m].name).materials.push_back(static_cast<int>(m));
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const Light& light = scene.lights[l];
    groupNamed(light.group.empty() ? lightTypeName(light.type) + std::to_string(l) : light.group)
        .lights.push_back(l);
  }
  std::map<std::string, std::string> byFile;
  for (const LightGroup& g : groups) {
    auto [it, added] = byFile.emplace(g.fileName, g.name);
    if (!added)
      throw InputError(scene.sourcePath, 0,
                       "light groups '" + it->second + "' and '" + g.name +
                           "' would write the same files (" + g.fileName +
                           "): rename one (the lights file's \"group\" or the material)");
  }
  return groups;
}

}  // namespace rad
