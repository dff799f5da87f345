#pragma once

// What a bake did, step by step (each step of bakeSolution adds its part, as the solve's stages
// add to SolveReport), and bake.json, assembled from it in one place.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/output/lightmap_confidence.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/scene/light_groups.h"

namespace rad {

// Parts of BakeReport, defined before it: std::optional of a nested struct with default member
// initialisers is not default-constructible inside its enclosing class for clang.
// The lightmap's layout and texels (none with --no-lightmap).
struct BakeLightmapFacts {
  bool sceneUvs = false;
  size_t charts = 0;
  int pages = 0, width = 0, height = 0;
  double texelSize = 0;
  std::string sizeRule;  // which rule chose the texel size (layoutLightmap)
  int padding = 0, dilation = 0;
  size_t covered = 0, conservative = 0, dilated = 0, empty = 0;  // texels by TexelState
  size_t nextToTwoCharts = 0;  // texels where bilinear filtering bleeds between charts
  int gatherRays = 0, lightRays = 0;
  LightmapContent content = LightmapContent::Radiance;
  double chartSeconds = 0, bakeSeconds = 0;
};

// How far to trust the texels (the "error" EXR channel).
struct BakeConfidence {
  std::string includes;  // which errors the estimate holds
  ConfidenceSummary summary;
  double seconds = 0;
};

// --directional: the L1 SH pages.
struct BakeDirectional {
  int rays = 0, pages = 0;
  double seconds = 0;
};

struct BakeReport {
  // The solution baked.
  std::string scene;
  std::vector<std::string> textureFallbacks;  // textures not read: their material's colour used
  int elements = 0, patches = 0;
  double toneMapExposure = 0;  // the 8-bit outputs' exposure
  double solveSeconds = 0;
  bool reusedSavedSolution = false;

  // The lightmap's layout and texels (none with --no-lightmap).
  using LightmapFacts = BakeLightmapFacts;
  std::optional<LightmapFacts> lightmap;

  // How far to trust the texels (the "error" EXR channel).
  using Confidence = BakeConfidence;
  std::optional<Confidence> confidence;

  // --light-groups: one layer per group, in the solution's order.
  struct Group {
    LightGroup group;
    std::vector<std::string> emissiveMaterials;  // the names of group.materials
  };
  std::vector<Group> lightGroups;

  // --directional: the L1 SH pages.
  using Directional = BakeDirectional;
  std::optional<Directional> directional;

  std::vector<SkipNote> skipped;

  // What writing the files adds: the base-colour images the glTF keeps (with a lightmap) and
  // the seconds from the solve's end to bake.json.
  std::optional<size_t> baseColourImages;
  double exportSeconds = 0;
};

// bake.json: every field of `report`, named and with units.
nlohmann::json bakeJson(const BakeReport& report);

}  // namespace rad
