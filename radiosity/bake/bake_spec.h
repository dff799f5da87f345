#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "radiosity/output/lightmap_content.h"
#include "radiosity/render/final_gather_options.h"

namespace rad {

// How the lightmap's charts are laid out on pages (the inputs of layoutLightmap).
struct LightmapLayoutSpec {
  double texelSize = 0;     // scene units per texel; 0: not given
  double texelDensity = 0;  // texels per scene unit; 0: not given
  int lightmapSize = 0;     // the side of one page (alone) or the largest page side; 0: not given
  int padding = 2;          // empty texels around each chart, each side
  double chartAngle = 30;   // the largest normal angle within one chart, degrees
  bool sceneUvs = false;    // the scene's own texture coordinates instead of generated charts
};

// What a bake makes of a solution (`radiosity bake`'s options, checked by the command).
struct BakeSpec {
  std::string scenePath;  // names the scene in messages and in bake.json
  LightmapLayoutSpec layout;
  bool lightmap = true;  // false: vertex colours only (--no-lightmap)
  int dilation = 2;      // rings of texels filled around each chart, at most layout.padding
  // Per texel: the rays of the final gather or of the direct/indirect split
  // (render/final_gather_options.h); none: the solution interpolated.
  FinalGatherOptions gather = {0, 0};
  LightmapContent content = LightmapContent::Radiance;
  bool directional = false;        // L1 SH pages of the incident light beside the lightmap
  int directionalRays = 64;        // hemisphere rays per texel of the directional pages
  uint64_t seed = 0;               // the texels' random streams (the solve's --seed)
  std::optional<double> exposure;  // the 8-bit outputs' exposure; none: the solution's own
};

}  // namespace rad
