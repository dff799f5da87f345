#include "radiosity/bake/bake_solution.h"

#include <chrono>

#include "radiosity/bake/bake_rays.h"
#include "radiosity/bake/confidence_pages.h"
#include "radiosity/bake/directional_pages.h"
#include "radiosity/bake/light_group_layers.h"
#include "radiosity/bake/lightmap_pages.h"
#include "radiosity/core/check.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/solution_tone_map.h"
#include "radiosity/scene/surface_textures.h"

namespace rad {
namespace {

// The vertices weighted by the elements' exposed areas (a buried part does not darken its
// neighbours), B/π at each for the whole and for every light group's layer, and the exposure.
BakeResult interpolateVertices(const Solution& solution, const BakeSpec& spec) {
  BakeResult result(VertexInterpolation(*solution.mesh, solution.problem.area));
  result.vertexRadiance =
      interpolateVertexRadiance(result.interpolation, solution.radiosity, solution.pointRadiosity);
  for (const LightLayer& layer : solution.layers)
    result.layerVertexRadiance.push_back(
        interpolateVertexRadiance(result.interpolation, layer.radiosity, layer.pointRadiosity));
  result.toneMap = spec.exposure ? ToneMap{*spec.exposure} : solutionToneMap(solution);
  return result;
}

// What bake.json says of the solution baked.
void reportSolution(const SolveResult& solved, const BakeSpec& spec, BakeResult& result) {
  BakeReport& report = result.report;
  report.scene = spec.scenePath;
  report.textureFallbacks = solved.solution.scene.textureFallbacks;
  report.elements = solved.solution.mesh->elementCount();
  report.patches = solved.solution.mesh->patchCount();
  report.toneMapExposure = result.toneMap.exposure;
  report.solveSeconds = solved.report.times.total;
  report.reusedSavedSolution = solved.report.reusedSavedSolution;
}

// The charts on their pages: the plan's, or laid out now on the solved mesh.
LaidOutLightmap layOutCharts(const Solution& solution, const BakeSpec& spec,
                             const LightmapPlan& plan, double& chartSeconds) {
  const auto start = std::chrono::steady_clock::now();
  LaidOutLightmap laidOut =
      plan.laidOut ? *plan.laidOut : layoutLightmap(*solution.mesh, spec.layout, spec.scenePath);
  chartSeconds = plan.seconds + secondsSince(start);
  return laidOut;
}

// Le per element: its texture's average over it, as the solve had it.
std::vector<Rgb> elementEmissions(const Solution& solution) {
  std::vector<Rgb> le(solution.mesh->elementCount());
  for (int e = 0; e < solution.mesh->elementCount(); ++e)
    le[e] = elementEmission(solution.scene, *solution.mesh, e);
  return le;
}

// The layout and the texels' states in `report.lightmap`; the log, and a warning where bilinear
// filtering bleeds between charts (scene UVs whose islands lie too close).
void reportLightmap(const BakeResult& result, const BakeSpec& spec, const std::string& rule,
                    double chartSeconds, double bakeSeconds, BakeReport& report) {
  const LightmapLayout& layout = result.layout;
  BakeReport::LightmapFacts& l = report.lightmap.emplace();
  auto count = [&](TexelState state) {
    size_t n = 0;
    for (const Lightmap& page : result.lightmaps) n += page.count(state);
    return n;
  };
  for (const Lightmap& page : result.lightmaps) l.nextToTwoCharts += page.crowdedTexels;
  if (l.nextToTwoCharts > 0)
    logWarning(spec.scenePath + ": " + std::to_string(l.nextToTwoCharts) +
               " texels lie next to two UV islands (islands less than 2 texels apart at " +
               std::to_string(layout.width) + "×" + std::to_string(layout.height) +
               "): bilinear filtering bleeds there; space the islands or lower --lightmap-size");
  logInfo("lightmap: " + std::string(spec.layout.sceneUvs ? "the scene's UVs, " : "") +
          std::to_string(layout.rects.size()) + " charts on " + std::to_string(layout.pages) +
          " page(s) of " + std::to_string(layout.width) + "×" + std::to_string(layout.height) +
          " texels of " + formatNumber(layout.texelSize) + " scene units (" + rule + ")");
  l.sceneUvs = spec.layout.sceneUvs;
  l.charts = layout.rects.size();
  l.pages = layout.pages;
  l.width = layout.width;
  l.height = layout.height;
  l.texelSize = layout.texelSize;
  l.sizeRule = rule;
  l.padding = layout.padding;
  l.dilation = spec.dilation;
  l.covered = count(TexelState::Covered);
  l.conservative = count(TexelState::Conservative);
  l.dilated = count(TexelState::Dilated);
  l.empty = count(TexelState::Empty);
  l.gatherRays = spec.gather.gatherRays;
  l.lightRays = spec.gather.shadowRays();
  l.content = spec.content;
  l.chartSeconds = chartSeconds;
  l.bakeSeconds = bakeSeconds;
}

}  // namespace

BakeResult bakeSolution(const SolveResult& solved, const SolveOptions& solveOptions,
                        const BakeSpec& spec, const LightmapPlan& plan) {
  const Solution& solution = solved.solution;
  RAD_CHECK(solution.layers.empty() || !spec.gather.castsRays());
  BakeResult result = interpolateVertices(solution, spec);
  reportSolution(solved, spec, result);
  reportLightGroups(solution, result.report);
  if (!spec.lightmap) {
    result.report.skipped.push_back(
        {"lightmap, scene_baked.obj", "--no-lightmap: vertex colours only"});
    logInfo("skipping the lightmap (--no-lightmap): vertex colours only");
    return result;
  }
  double chartSeconds = 0;
  const LaidOutLightmap laidOut = layOutCharts(solution, spec, plan, chartSeconds);
  result.layout = laidOut.layout;
  const auto start = std::chrono::steady_clock::now();
  BakeRays rays(solution);
  // The parts of elements no light reaches, as the solve found them (found again when it did
  // not keep them: refinement changed the mesh, or a saved solution without them).
  const ElementExposure exposure = solution.exposure
                                       ? *solution.exposure
                                       : solveExposure(solveOptions, *solution.mesh, rays.caster());
  const std::vector<Rgb> elementLe = elementEmissions(solution);
  LightmapPages pages(solution, result.layout, result.interpolation, exposure, spec, rays);
  result.lightmaps = pages.bake({solution.radiosity, result.vertexRadiance, elementLe});
  result.errorPages = bakeConfidence(solution, result.layout, result.lightmaps, spec,
                                     pages.gatherError(), exposure, result.report);
  result.layerLightmaps =
      lightGroupPages(solution, pages, result.layerVertexRadiance, elementLe, result.lightmaps);
  reportLightmap(result, spec, laidOut.rule, chartSeconds, secondsSince(start), result.report);
  if (spec.directional)
    result.directionalPages = bakeDirectionalPages(rays.view(), solution, result.layout,
                                                   result.interpolation, spec, result.report);
  return result;
}

}  // namespace rad
