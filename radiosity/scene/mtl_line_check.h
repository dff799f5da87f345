#pragma once

#include <string>
#include <vector>

#include "radiosity/scene/mtl_texture_map.h"

namespace rad {

// Where a material was defined (the `newmtl` line).
struct MaterialSource {
  std::string name;
  std::string file;
  int line = 0;
  // The material's colour, emission and coverage images (`map_Kd`, `map_Ke`, `map_d`).
  TextureMapStatement diffuseMap, emissionMap, coverageMap;
};

// The result of checking one MTL library line by line.
struct MtlLineCheck {
  std::vector<MaterialSource> materials;  // in definition order, as tinyobjloader numbers them
  std::string text;  // the library for tinyobjloader: comments removed, whitespace normalised
};

// Validates an MTL library: every statement about a material follows a `newmtl`; material names
// are single words; Kd, Ke, Ks, Tf/Kt take exactly 3 finite numbers, Ni and Ns one, illum one
// integer; Kd lies in [0, 1] (1 with a warning, unless a map_Kd multiplies it) and Ke is
// non-negative in every channel;
// `map_Kd`, `map_Ke` and `map_d` are read by parseTextureMap (the images are loaded later). Throws
// InputError with "file:line: message" at the first offending line.
MtlLineCheck checkMtlText(const std::string& text, const std::string& file);

}  // namespace rad
