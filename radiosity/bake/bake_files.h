#pragma once

// The names of the files a bake writes, for the writer and for bake.json's lists alike.
#include <string>
#include <vector>

#include "radiosity/scene/light_groups.h"

namespace rad {

// lightmap.EXT for one page; lightmap_0.EXT, lightmap_1.EXT, … for several.
std::string lightmapFileName(int page, int pages, const std::string& extension);

// A light group's file: the whole's name after the group's ("group_warm_lightmap.exr").
std::string groupFileName(const LightGroup& group, const std::string& name);

// A light group's files, as bake.json lists them: its vertex colours, then per page (when there
// is a lightmap of `pages` pages) its EXR and PNG.
std::vector<std::string> groupFileNames(const LightGroup& group, int pages, bool lightmap);

// The directional pages' files, per page its four coefficient EXRs (directionalCoefficientNames'
// order) and its direction PNG.
std::vector<std::string> directionalFileNames(int pages);

}  // namespace rad
