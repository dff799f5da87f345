#include "radiosity/bake/bake_report.h"

#include "radiosity/bake/bake_files.h"
#include "radiosity/render/directional_lightmap.h"

namespace rad {
namespace {

nlohmann::json lightmapJson(const BakeReport::LightmapFacts& l) {
  return {{"uvs", l.sceneUvs ? "scene" : "generated"},
          {"charts", l.charts},
          {"pages", l.pages},
          {"width", l.width},
          {"height", l.height},
          {"texel_size", l.texelSize},
          {"texel_density", 1 / l.texelSize},
          {"size_rule", l.sizeRule},
          {"padding", l.padding},
          {"dilation", l.dilation},
          {"texels_covered", l.covered},
          {"texels_conservative", l.conservative},
          {"texels_dilated", l.dilated},
          {"texels_empty", l.empty},
          {"texels_next_to_two_charts", l.nextToTwoCharts},
          {"chart_seconds", l.chartSeconds},
          {"gather_rays", l.gatherRays},
          {"light_rays", l.lightRays},
          {"bake_seconds", l.bakeSeconds},
          {"content", lightmapContentName(l.content)},
          {"unit", lightmapContentMeaning(l.content)}};
}

nlohmann::json confidenceJson(const BakeReport::Confidence& c) {
  return {{"exr_channel", "error"},
          {"unit",
           "estimated absolute error of the texel's luminance (Rec. 709 of the per-channel "
           "errors), in the unit of the lightmap"},
          {"includes", c.includes},
          {"left_out",
           "the solution's own error (form-factor ray noise, element means) where it "
           "reaches the texel through the interpolated or gathered light"},
          {"texels", c.summary.texels},
          {"median_relative_error", c.summary.medianRelative},
          {"p95_relative_error", c.summary.p95Relative},
          {"fraction_above_10_percent", c.summary.fractionAbove10Percent},
          {"seconds", c.seconds}};
}

// One entry per layer: the group, its glb attribute and its files.
nlohmann::json lightGroupsJson(const BakeReport& report) {
  const int pages = report.lightmap ? report.lightmap->pages : 0;
  nlohmann::json groups = nlohmann::json::array();
  for (size_t g = 0; g < report.lightGroups.size(); ++g) {
    const LightGroup& group = report.lightGroups[g].group;
    nlohmann::json lights = nlohmann::json::array();
    for (size_t l : group.lights) lights.push_back(l);
    groups.push_back({{"name", group.name},
                      {"emissive_materials", report.lightGroups[g].emissiveMaterials},
                      {"lights", lights},
                      {"glb_attribute", "_LIGHT_GROUP_" + std::to_string(g)},
                      {"files", groupFileNames(group, pages, report.lightmap.has_value())}});
  }
  return groups;
}

nlohmann::json directionalJson(const BakeReport::Directional& d) {
  return {{"files", directionalFileNames(d.pages)},
          {"rays", d.rays},
          {"convention", kDirectionalConvention},
          {"unit", "W/m^2 (coefficients of radiance in W/(m^2 sr))"},
          {"seconds", d.seconds}};
}

}  // namespace

nlohmann::json bakeJson(const BakeReport& report) {
  nlohmann::json json = {{"scene", report.scene},
                         {"elements", report.elements},
                         {"patches", report.patches},
                         {"tone_map_exposure", report.toneMapExposure},
                         {"solve_seconds", report.solveSeconds},
                         {"reused_saved_solution", report.reusedSavedSolution},
                         {"texture_fallbacks", report.textureFallbacks}};
  if (report.lightmap) json["lightmap"] = lightmapJson(*report.lightmap);
  if (report.confidence) json["confidence"] = confidenceJson(*report.confidence);
  if (!report.lightGroups.empty()) json["light_groups"] = lightGroupsJson(report);
  if (report.directional) json["directional"] = directionalJson(*report.directional);
  if (!report.skipped.empty()) {
    nlohmann::json skipped = nlohmann::json::array();
    for (const SkipNote& s : report.skipped) skipped.push_back({{"what", s.what}, {"why", s.why}});
    json["skipped"] = skipped;
  }
  if (report.baseColourImages) json["base_colour_images"] = *report.baseColourImages;
  json["export_seconds"] = report.exportSeconds;
  return json;
}

}  // namespace rad
