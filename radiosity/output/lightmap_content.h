#pragma once

#include <string>

#include "radiosity/core/named_values.h"

namespace rad {

// What a baked lightmap's texels hold (`bake --lightmap-content`).
enum class LightmapContent {
  // The outgoing radiance L (W·m⁻²·sr⁻¹), the surface's texture included: shown as it is.
  Radiance,
  // The albedo-free incident light H/π = (B − E)/(π ρ_element) (W·m⁻²·sr⁻¹): engines multiply it
  // by the base colour at run time. 0 on surfaces of reflectance 0, which keep no record of it.
  Irradiance,
};

// The command line's and the reports' names, the one list of them.
inline const NameTable<LightmapContent>& lightmapContentTable() {
  static const NameTable<LightmapContent> table = {{"radiance", LightmapContent::Radiance},
                                                   {"irradiance", LightmapContent::Irradiance}};
  return table;
}

inline std::string lightmapContentName(LightmapContent content) {
  return nameOf(lightmapContentTable(), content);
}

// One line for the exports' metadata (bake.json, the glTF's asset.extras).
inline std::string lightmapContentMeaning(LightmapContent content) {
  return content == LightmapContent::Radiance
             ? "outgoing radiance L, W m^-2 sr^-1, textures included: display as is"
             : "incident irradiance over pi, H/pi = (B - E)/(pi rho), W m^-2 sr^-1: multiply by "
               "the base colour for the reflected radiance; 0 where rho = 0";
}

}  // namespace rad
