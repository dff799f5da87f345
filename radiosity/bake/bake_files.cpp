#include "radiosity/bake/bake_files.h"

#include "radiosity/render/directional_lightmap.h"

namespace rad {

std::string lightmapFileName(int page, int pages, const std::string& extension) {
  return pages == 1 ? "lightmap." + extension
                    : "lightmap_" + std::to_string(page) + "." + extension;
}

std::string groupFileName(const LightGroup& group, const std::string& name) {
  return "group_" + group.fileName + "_" + name;
}

std::vector<std::string> groupFileNames(const LightGroup& group, int pages, bool lightmap) {
  std::vector<std::string> files = {groupFileName(group, "vertex_colors.ply")};
  if (lightmap)
    for (int page = 0; page < pages; ++page) {
      files.push_back(groupFileName(group, lightmapFileName(page, pages, "exr")));
      files.push_back(groupFileName(group, lightmapFileName(page, pages, "png")));
    }
  return files;
}

std::vector<std::string> directionalFileNames(int pages) {
  std::vector<std::string> names;
  for (int page = 0; page < pages; ++page) {
    for (const char* k : directionalCoefficientNames())
      names.push_back(directionalFileName(page, pages, std::string(k) + ".exr"));
    names.push_back(directionalFileName(page, pages, "direction.png"));
  }
  return names;
}

}  // namespace rad
