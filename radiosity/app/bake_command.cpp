// `radiosity bake SCENE.obj --out DIR`: the solution baked into a lightmap atlas and into exports
// that game engines and DCC tools load (glTF binary, OBJ + MTL, PLY vertex colours).
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "meshing/lightmap_charts.h"
#include "meshing/lightmap_packing.h"
#include "meshing/mesh_uv_layout.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/app/baked_materials.h"
#include "radiosity/app/commands.h"
#include "radiosity/app/options/exposure_option.h"
#include "radiosity/app/options/gather_options.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/output/display_radiance.h"
#include "radiosity/output/gltf_export.h"
#include "radiosity/output/image_io.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/output/lightmap_baked_mesh.h"
#include "radiosity/output/lightmap_confidence.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/output/obj_export.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/pipeline/solution_source.h"
#include "radiosity/pipeline/solution_tone_map.h"
#include "radiosity/pipeline/thread_limit.h"
#include "radiosity/render/directional_lightmap.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sobol_sampler.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/surface_textures.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

struct BakeOptions {
  SolveOptions solve;
  double texelSize = 0;     // --texel-size, scene units per texel; 0: not given
  double texelDensity = 0;  // --texel-density, texels per scene unit; 0: not given
  int lightmapSize = 0;     // --lightmap-size; 0: not given
  int padding = 2;
  int dilation = -1;  // -1: the padding
  double chartAngle = 30;
  bool noLightmap = false;
  bool sceneUvs = false;  // bake into the scene's own texture coordinates
  // Per texel: --gather, --light-rays; none: the solution interpolated.
  FinalGatherOptions gather = {0, 0};
  std::string solutionDir;  // --solution: reuse the solution `solve` saved there
  ExposureOption exposure;  // --exposure: fixed instead of automatic
  LightmapContent content = LightmapContent::Radiance;  // --lightmap-content
  bool directional = false;  // --directional: L1 SH texels beside the lightmap
  int directionalRays = 64;  // --directional-rays: hemisphere rays per texel
};

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The lightmap atlas of `mesh` as the options ask, and which rule chose its texel size (for the
// log and bake.json). The one place that decides:
//   --lightmap-size alone      one square page of that side, the densest texels that fit;
//   --texel-size/-density      that density, on as many pages as needed of at most
//                              --lightmap-size (default kDefaultMaxLightmapPage) texels a side;
//   neither                    the scene's default density (defaultTexelSize), pages as above.
// With the scene's UVs there is one page, its side from the density (at most the page size when
// the density is the default). InputError naming the scene when the charts do not fit.
LightmapLayout layoutLightmap(const PatchMesh& mesh, const BakeOptions& o, std::string& rule) {
  const double asked = o.texelSize > 0 ? o.texelSize : o.texelDensity > 0 ? 1 / o.texelDensity : 0;
  const bool onePage = o.lightmapSize > 0 && asked == 0;
  const double texelSize = onePage ? 0 : asked > 0 ? asked : defaultTexelSize(mesh);
  const int maxPage = o.lightmapSize > 0 ? o.lightmapSize : kDefaultMaxLightmapPage;
  std::ostringstream why;
  if (onePage)
    why << "--lightmap-size " << o.lightmapSize << ": the densest texels that fit one page";
  else if (asked > 0)
    why << (o.texelSize > 0 ? "--texel-size" : "--texel-density") << ", pages of at most "
        << maxPage << "²";
  else
    why << "default: " << formatNumber(kDefaultLightmapTexels) << " texels over the scene's "
        << formatNumber(kDefaultLightmapTexels * texelSize * texelSize)
        << " units² of surface, pages of at most " << maxPage << "²";
  rule = why.str();
  try {
    if (o.sceneUvs) {
      int side = o.lightmapSize;
      if (asked > 0)
        side = atlasSideForTexelSize(mesh, asked, o.lightmapSize > 0 ? o.lightmapSize : 16384);
      else if (!onePage)
        side = std::min(kDefaultMaxLightmapPage,
                        atlasSideForTexelSize(mesh, texelSize, std::numeric_limits<int>::max()));
      return layoutFromMeshUvs(mesh, side, side, o.padding);
    }
    return packLightmapCharts(buildLightmapCharts(mesh, {o.chartAngle}),
                              {texelSize, onePage ? o.lightmapSize : 0, o.padding, maxPage});
  } catch (const InputError& e) {
    // The options do not fit this scene's charts: name the scene.
    if (!e.file().empty()) throw;
    throw InputError(o.solve.scenePath, 0, e.what());
  }
}

// lightmap.EXT for one page; lightmap_0.EXT, lightmap_1.EXT, … for several.
std::string lightmapFileName(int page, int pages, const std::string& extension) {
  return pages == 1 ? "lightmap." + extension
                    : "lightmap_" + std::to_string(page) + "." + extension;
}

// A light group's file: the whole's name after the group's ("group_warm_lightmap.exr").
std::string groupFileName(const LightGroup& group, const std::string& name) {
  return "group_" + group.fileName + "_" + name;
}

// The confidence map (docs/baking.md, "How far to trust each texel"): per page, the estimated
// absolute error of each texel's value per channel (W·m⁻²·sr⁻¹), rasterised and dilated like
// the values. Without a gather: the mesh's displayed error (displayedError, the refinement's
// estimate) of what the texel interpolates, scaled as bakePages forms the value: the radiance's
// own; the light arriving (H/π) times the texel's ρ where a texture multiplies it; H/π's alone
// for irradiance content; 0 where the texel is buried (its value, the emission alone, is exact).
// With --gather: the gather's standard error (`gatherError`, per page and
// texel; ÷ ρ for irradiance content). The gather reads the solution one bounce away, averaged
// over many elements, so the mesh's displayed error does not apply there. Left out: the
// solution's own error (its form-factor rays' noise, its elements' means) where it reaches the
// texel through the gathered light, or through the interpolated values.
std::vector<Lightmap> confidencePages(const Solution& solution, const LightmapLayout& layout,
                                      const std::vector<Lightmap>& lightmaps,
                                      LightmapContent content,
                                      const std::vector<std::vector<Rgb>>& gatherError,
                                      const ElementExposure& exposure) {
  const PatchMesh& mesh = *solution.mesh;
  const Scene& scene = solution.scene;
  const bool irradiance = content == LightmapContent::Irradiance;
  const bool textured = irradiance || !scene.textures.empty();
  const int n = mesh.elementCount();
  std::vector<Rgb> radianceError, incidentError;
  if (gatherError.empty()) {
    std::vector<Rgb> radiance(n);
    for (int e = 0; e < n; ++e) radiance[e] = solution.radiosity[e] / M_PI;
    std::vector<std::array<Rgb, 3>> points = solution.pointRadiosity;
    for (auto& p : points)
      for (Rgb& b : p) b = b / M_PI;
    // The two estimates side by side (each walks the mesh's corners per channel).
    tbb::parallel_invoke([&] { radianceError = displayedError(mesh, radiance, points); },
                         [&] {
                           if (!textured) return;
                           std::vector<Rgb> incident(n);
                           for (int e = 0; e < n; ++e)
                             incident[e] = incidentLight(solution.radiosity[e],
                                                         M_PI * elementEmission(scene, mesh, e),
                                                         solution.problem.reflectance[e]) /
                                           M_PI;
                           incidentError = displayedError(mesh, incident);
                         });
  }
  auto overRho = [](Rgb v, const Rgb& rho) {
    for (int c = 0; c < 3; ++c) v[c] = rho[c] > 0 ? v[c] / rho[c] : 0;
    return v;
  };
  std::vector<Lightmap> pages;
  for (int page = 0; page < layout.pages; ++page)
    pages.push_back(bakeOnTexels(
        lightmaps[page], layout, [&](int e, const Eigen::Vector3d& b, size_t texel) -> Rgb {
          if (!gatherError.empty()) {
            const Rgb& error = gatherError[page][texel];
            return irradiance ? overRho(error, reflectanceAt(scene, mesh, e, b[1], b[2])) : error;
          }
          // Buried: exactly the texel's own emission (no light arrives), nothing to be wrong about.
          if (exposure.buriedAtBarycentric(e, b[1], b[2])) return Rgb();
          if (irradiance) return incidentError[e];
          if (textured && hasReflectanceTexture(scene, mesh, e))
            return reflectanceAt(scene, mesh, e, b[1], b[2]) * incidentError[e];
          return radianceError[e];
        }));
  return pages;
}

// What only the lightmap reads: with --no-lightmap (vertex colours only), an error when given.
// (--use-scene-uvs and --chart-angle exclude --no-lightmap on the command line, --directional
// has its own rule below.)
const char* const kLightmapOnlyOptions[] = {"--texel-size", "--texel-density",   "--lightmap-size",
                                            "--padding",    "--dilation",        "--gather",
                                            "--light-rays", "--lightmap-content"};

// Every bake option the chosen mode does not use, given, is an error saying why; so are values
// that cannot work together. Before anything is solved or written. Sets --dilation's default.
void checkBakeOptions(const CLI::App& command, BakeOptions& o) {
  finishSolveOptions(command, o.solve);
  o.exposure.check();
  checkGatherOptions(o.gather);
  if (o.noLightmap)
    for (const char* name : kLightmapOnlyOptions)
      refuseIfGiven(command, name, "--no-lightmap bakes vertex colours only, no lightmap");
  if (command.count("--directional-rays") > 0 && !o.directional)
    throw InputError(
        "--directional-rays sets the rays of --directional's texels: add --directional");
  if (o.directional && o.noLightmap)
    throw InputError(
        "--directional with --no-lightmap: the directional texels are lightmap pages beside "
        "lightmap.exr; drop --no-lightmap");
  if (o.directional && o.solve.lightGroups)
    throw InputError(
        "--directional with --light-groups: the directional texels hold the whole scene's light, "
        "not one layer per group; bake the groups and the directional lightmap separately");
  if (o.solve.lightGroups && o.gather.castsRays())
    throw InputError(
        "--gather with --light-groups: the per-texel gather samples every light at once, so it "
        "cannot split its direct light into the groups; bake the layers without --gather (or "
        "refine the mesh with --element-size for sharper shadows)");
  if (o.dilation < 0) o.dilation = o.padding;
  if (o.dilation > o.padding)
    throw InputError("--dilation " + std::to_string(o.dilation) + " exceeds --padding " +
                     std::to_string(o.padding) +
                     ": dilated texels of neighbouring charts would meet");
}

void runBake(const CLI::App& command, BakeOptions& o) {
  checkBakeOptions(command, o);
  // --threads caps the whole bake (gather, rasterising, EXR compression), not the solve alone.
  const ThreadLimit threadLimit(o.solve.threads);
  const int threads = threadLimit.threads();
  // The scene's UVs are checked before the solve, so a bad layout fails in seconds.
  const auto loadStart = std::chrono::steady_clock::now();
  Scene scene = loadScene(o.solve.scenePath, o.solve.lights, o.solve.twoSided);
  if (o.sceneUvs) checkLightmapUvs(scene);
  const double loadSeconds = since(loadStart);
  // Whether the charts fit is decided before the solve, on the mesh the solve starts from: a
  // lightmap size that cannot hold them fails in seconds, not after the solve. Uniform meshing is
  // deterministic, so without refinement that layout is the solved mesh's own.
  LightmapLayout layout;
  std::string layoutRule;
  bool earlyLayout = false;
  double chartSeconds = 0;
  // With --solution nothing is solved (a solution that does not fit is refused in seconds): the
  // charts are laid out once, on the saved solution's mesh, not on a mesh made for the plan.
  if (!o.noLightmap && o.solutionDir.empty()) {
    const auto t = std::chrono::steady_clock::now();
    checkSceneLimits(scene);  // as the solve does before it meshes
    const LightmapLayout planned = layoutLightmap(*meshScene(scene, o.solve).mesh, o, layoutRule);
    earlyLayout = !(o.solve.refineThreshold > 0);
    if (earlyLayout) layout = planned;
    chartSeconds = since(t);
    logInfo("lightmap plan: " + std::to_string(planned.rects.size()) + " charts on " +
            std::to_string(planned.pages) + " page(s) of " + std::to_string(planned.width) + "×" +
            std::to_string(planned.height) + ", " + formatNumber(1 / planned.texelSize) +
            " texels per scene unit (" + layoutRule + ")");
  }
  // A solution `solve` (or an earlier render) saved in --out is reused when it matches.
  SolveResult result = solveOrReuse(std::move(scene), o.solve, {o.solutionDir, o.solve.outputDir});
  result.report.times.load = loadSeconds;
  result.report.times.total += loadSeconds;
  const Solution& solution = result.solution;
  const PatchMesh& mesh = *solution.mesh;
  const auto start = std::chrono::steady_clock::now();

  const VertexInterpolation interpolation(mesh, solution.problem.area);  // exposed areas
  const std::vector<Rgb> vertexRadiance =
      interpolateVertexRadiance(interpolation, solution.radiosity, solution.pointRadiosity);
  std::vector<std::vector<Rgb>> layerVertexRadiance;  // per light group (--light-groups)
  for (const LightLayer& layer : solution.layers)
    layerVertexRadiance.push_back(
        interpolateVertexRadiance(interpolation, layer.radiosity, layer.pointRadiosity));
  const ToneMap toneMap = o.exposure.toneMap([&] { return solutionToneMap(solution); });
  std::vector<std::string> materialNames;
  for (const Material& m : solution.scene.materials) materialNames.push_back(m.name);

  nlohmann::json summary = {{"scene", o.solve.scenePath},
                            {"elements", mesh.elementCount()},
                            {"patches", mesh.patchCount()},
                            {"tone_map_exposure", toneMap.exposure},
                            {"solve_seconds", result.report.times.total},
                            {"reused_saved_solution", result.report.reusedSavedSolution}};
  std::vector<Lightmap> lightmaps;                    // one per page
  std::vector<Lightmap> errorPages;                   // the confidence map, one per page
  std::vector<std::vector<Lightmap>> layerLightmaps;  // per light group, one per page
  // --directional: the L1 SH pages, one per page.
  std::vector<DirectionalLightmapPage> directionalPages;
  BakedLook look;
  if (!o.noLightmap) {
    auto t = std::chrono::steady_clock::now();
    if (!earlyLayout) layout = layoutLightmap(mesh, o, layoutRule);
    chartSeconds += since(t);
    t = std::chrono::steady_clock::now();
    // Per element: the reflectance and emission it was solved with (textures' averages), from
    // which a texel's own texture colour, or the albedo-free light, follows.
    const std::vector<Rgb>& elementRho = solution.problem.reflectance;
    std::vector<Rgb> elementLe(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e)
      elementLe[e] = elementEmission(solution.scene, mesh, e);
    auto texelRho = [&](int e, const Eigen::Vector3d& b) {
      return reflectanceAt(solution.scene, mesh, e, b[1], b[2]);
    };
    const bool irradiance = o.content == LightmapContent::Irradiance;
    // The parts of elements no light reaches (the floor under a box standing on it, the ceiling
    // behind a one-sided lamp), as the solve finds them: their texels hold no arriving light, not
    // the interpolated light of the element's exposed part (measured on the Cornell box: 3.3% of
    // the texels, which made the interpolated lightmap 1.55% brighter than Cycles' bake).
    // The BVH only where rays are cast: the buried parts when the solve did not keep them, the
    // gather, the directional pages.
    std::unique_ptr<const RayCaster> caster;
    auto rays = [&]() -> const RayCaster& {
      if (!caster) caster = std::make_unique<const RayCaster>(mesh, solution.scene);
      return *caster;
    };
    const ElementExposure exposure =
        solution.exposure ? *solution.exposure : solveExposure(o.solve, mesh, rays());
    std::unique_ptr<const RenderScene> view;
    std::unique_ptr<const FinalGather> gather;
    std::vector<std::vector<Rgb>> gatherError;  // per page and texel: the gather's standard error
    const bool textured = irradiance || !solution.scene.textures.empty();
    // --gather N, or --gather 0 --light-rays N: the direct light per texel, the indirect part
    // the solution's (final_gather.h).
    if (o.gather.castsRays()) {
      view = std::make_unique<const RenderScene>(solution.scene, mesh, rays());
      gather = std::make_unique<const FinalGather>(*view, solution.radiosity, o.gather);
      gatherError.assign(layout.pages,
                         std::vector<Rgb>(static_cast<size_t>(layout.width) * layout.height));
    }
    // The pages of one solution (the whole, or one light group's layer with its own emitters'
    // Le): every step is linear in B and Le, so the layers' pages add up to the whole's. A
    // layer's pages are made on the texels of the whole's (`shape`), not rasterised again.
    auto bakePages = [&](const std::vector<Rgb>& radiosity, const std::vector<Rgb>& vertexValues,
                         const std::vector<Rgb>& le, const std::vector<Lightmap>* shape) {
      // H/π at the vertices: the light arriving, smooth across elements of different reflectance.
      std::vector<Rgb> vertexIncident;
      if (!gather && textured) {
        std::vector<Rgb> incident(mesh.elementCount());
        for (int e = 0; e < mesh.elementCount(); ++e)
          incident[e] = incidentLight(radiosity[e], M_PI * le[e], elementRho[e]);
        vertexIncident = interpolateVertexRadiance(interpolation, incident);
      }
      std::vector<Lightmap> pages;
      for (int page = 0; page < layout.pages; ++page) {
        if (gather) {
          // Per-texel final gather: direct light by shadow rays to the emitters and gathered
          // light from the solution at every texel, for shadows sharper than the elements. The
          // rays leave from points spread over the texel's footprint on its element: the texel
          // holds its box-filtered mean, as Cycles' bake and the engines' lightmappers give.
          const uint64_t seed = o.solve.seed;
          pages.push_back(bakeLightmap(
              mesh, layout, interpolation, vertexValues, o.dilation,
              [&](int e, const Eigen::Vector3d& b, size_t texel) {
                const uint64_t key = streamKey(seed, 0x6c6d6170ull + page, texel);  // per texel
                Rng rng(key);
                SobolSampler sampler(seed, key, rng);
                sampler.startSample(0);
                RayCounts counts;
                Rgb standardError;  // for the confidence map
                const TexelFootprint footprint = TexelFootprint::of(layout.texels[e], b);
                const Rgb out =
                    gather->outgoingRadiance(e, footprint, sampler, counts, standardError);
                gatherError[page][texel] = standardError;
                // Gathered at the texel with its own ρ: divide that one out.
                const Rgb& texelLe = solution.scene.materials[mesh.material(e)].emission;
                return irradiance ? incidentLight(out, texelLe, texelRho(e, b)) : out;
              },
              page));
        } else {
          // The interpolated solution, with the texture's detail inside each element (or
          // without the albedo at all); where the point is buried, what it emits alone.
          const TexelEvaluator interpolated = [&](int e, const Eigen::Vector3d& b, size_t) {
            if (exposure.buriedAtBarycentric(e, b[1], b[2])) return irradiance ? Rgb() : le[e];
            const auto& v = interpolation.triangle(e);
            auto at = [&](const std::vector<Rgb>& perVertex) {
              return perVertex[v[0]] * b[0] + perVertex[v[1]] * b[1] + perVertex[v[2]] * b[2];
            };
            if (irradiance) return at(vertexIncident);
            if (!textured || !hasReflectanceTexture(solution.scene, mesh, e))
              return at(vertexValues);
            return le[e] + texelRho(e, b) * at(vertexIncident);
          };
          pages.push_back(shape ? bakeOnTexels((*shape)[page], layout, interpolated)
                                : bakeLightmap(mesh, layout, interpolation, vertexValues,
                                               o.dilation, interpolated, page));
        }
      }
      return pages;
    };
    lightmaps = bakePages(solution.radiosity, vertexRadiance, elementLe, nullptr);
    {
      // The confidence map: the "error" channel of lightmap.exr, and its summary.
      const auto confidenceStart = std::chrono::steady_clock::now();
      errorPages = confidencePages(solution, layout, lightmaps, o.content, gatherError, exposure);
      const ConfidenceSummary c = summariseConfidence(lightmaps, errorPages);
      const std::string includes =
          o.gather.gatherRays > 0
              ? "the per-texel gather's Monte Carlo standard error (shadow and gather rays)"
          : o.gather.indirectFromSolution()
              ? "the per-texel direct light's Monte Carlo standard error (shadow rays; the "
                "indirect part is the solution's, interpolated)"
              : "the mesh's displayed error (the interpolated values against the "
                "solution, the refinement's estimate)";
      logInfo("lightmap confidence: " + describeConfidence(c) + "; " + includes);
      summary["confidence"] = {
          {"exr_channel", "error"},
          {"unit",
           "estimated absolute error of the texel's luminance (Rec. 709 of the per-channel "
           "errors), in the unit of the lightmap"},
          {"includes", includes},
          {"left_out",
           "the solution's own error (form-factor ray noise, element means) where it "
           "reaches the texel through the interpolated or gathered light"},
          {"texels", c.texels},
          {"median_relative_error", c.medianRelative},
          {"p95_relative_error", c.p95Relative},
          {"fraction_above_10_percent", c.fractionAbove10Percent},
          {"seconds", since(confidenceStart)}};
    }
    for (size_t g = 0; g < solution.layers.size(); ++g) {
      const LightGroup& group = solution.layers[g].group;
      std::vector<char> member(solution.scene.materials.size(), 0);
      for (int m : group.materials) member[m] = 1;
      std::vector<Rgb> groupLe(mesh.elementCount());
      for (int e = 0; e < mesh.elementCount(); ++e)
        if (member[mesh.material(e)]) groupLe[e] = elementLe[e];
      layerLightmaps.push_back(
          bakePages(solution.layers[g].radiosity, layerVertexRadiance[g], groupLe, &lightmaps));
    }
    size_t crowded = 0;
    auto count = [&](TexelState state) {
      size_t n = 0;
      for (const Lightmap& l : lightmaps) n += l.count(state);
      return n;
    };
    for (const Lightmap& l : lightmaps) crowded += l.crowdedTexels;
    if (crowded > 0)
      logWarning(o.solve.scenePath + ": " + std::to_string(crowded) +
                 " texels lie next to two UV islands (islands less than 2 texels apart at " +
                 std::to_string(layout.width) + "×" + std::to_string(layout.height) +
                 "): bilinear filtering bleeds there; space the islands or lower --lightmap-size");
    logInfo("lightmap: " + std::string(o.sceneUvs ? "the scene's UVs, " : "") +
            std::to_string(layout.rects.size()) + " charts on " + std::to_string(layout.pages) +
            " page(s) of " + std::to_string(layout.width) + "×" + std::to_string(layout.height) +
            " texels of " + formatNumber(layout.texelSize) + " scene units (" + layoutRule + ")");
    summary["lightmap"] = {{"uvs", o.sceneUvs ? "scene" : "generated"},
                           {"charts", layout.rects.size()},
                           {"pages", layout.pages},
                           {"width", layout.width},
                           {"height", layout.height},
                           {"texel_size", layout.texelSize},
                           {"texel_density", 1 / layout.texelSize},
                           {"size_rule", layoutRule},
                           {"padding", layout.padding},
                           {"dilation", o.dilation},
                           {"texels_covered", count(TexelState::Covered)},
                           {"texels_conservative", count(TexelState::Conservative)},
                           {"texels_dilated", count(TexelState::Dilated)},
                           {"texels_empty", count(TexelState::Empty)},
                           {"texels_next_to_two_charts", crowded},
                           {"chart_seconds", chartSeconds},
                           {"gather_rays", o.gather.gatherRays},
                           {"light_rays", o.gather.shadowRays()},
                           {"bake_seconds", since(t)},
                           {"content", lightmapContentName(o.content)},
                           {"unit", lightmapContentMeaning(o.content)}};
    if (o.directional) {
      // L1 SH of the incident radiance per texel, beside the lightmap
      // (render/directional_lightmap).
      t = std::chrono::steady_clock::now();
      if (!view) {
        view = std::make_unique<const RenderScene>(solution.scene, mesh, rays());
      }
      nlohmann::json names = nlohmann::json::array();
      for (int page = 0; page < layout.pages; ++page) {
        directionalPages.push_back(bakeDirectionalPage(*view, solution.radiosity, layout,
                                                       interpolation, o.dilation, page,
                                                       o.directionalRays, o.solve.seed));
        for (const char* k : directionalCoefficientNames())
          names.push_back(directionalFileName(page, layout.pages, std::string(k) + ".exr"));
        names.push_back(directionalFileName(page, layout.pages, "direction.png"));
      }
      summary["directional"] = {{"files", names},
                                {"rays", o.directionalRays},
                                {"convention", kDirectionalConvention},
                                {"unit", "W/m^2 (coefficients of radiance in W/(m^2 sr))"},
                                {"seconds", since(t)}};
      logInfo("directional lightmap: L1 SH of the incident light, " +
              std::to_string(o.directionalRays) + " rays per texel, " + formatNumber(since(t)) +
              " s");
    }
  } else {
    summary["skipped"] = {
        {{"what", "lightmap, scene_baked.obj"}, {"why", "--no-lightmap: vertex colours only"}}};
    logInfo("skipping the lightmap (--no-lightmap): vertex colours only");
  }
  // Everything goes under temporary names; only when all are complete do they take their names.
  throwIfInterrupted();
  OutputSection writing;  // Ctrl-C now waits until every file has its final name (or none has)
  ensureDirectory(o.solve.outputDir);
  const std::filesystem::path dir(o.solve.outputDir);
  // The EXR pages are compressed on OpenEXR's own threads while the rest is encoded and written
  // (a large page takes a few tenths of a second). `exrFiles` outlives `writingExrs`, whose
  // destructor waits for the writes: on a failure the temporary files go only once they are done.
  std::vector<std::unique_ptr<AtomicPath>> exrFiles;
  std::vector<std::function<void()>> exrWrites;
  auto exr = [&](const std::string& name, const ImageRgb& image, std::vector<ExrChannel> extra) {
    exrFiles.push_back(std::make_unique<AtomicPath>((dir / name).string()));
    exrWrites.push_back([file = exrFiles.back().get(), &image, extra = std::move(extra)] {
      writeExr(*file, image, extra);
    });
  };
  for (int page = 0; page < static_cast<int>(lightmaps.size()); ++page)
    exr(lightmapFileName(page, layout.pages, "exr"), lightmaps[page].radiance,
        {{"error", errorChannel(errorPages[page])}});
  for (size_t g = 0; g < layerLightmaps.size(); ++g)
    for (int page = 0; page < static_cast<int>(layerLightmaps[g].size()); ++page)
      exr(groupFileName(solution.layers[g].group, lightmapFileName(page, layout.pages, "exr")),
          layerLightmaps[g][page].radiance, {});
  for (size_t page = 0; page < directionalPages.size(); ++page)
    for (int k = 0; k < 4; ++k)
      exr(directionalFileName(static_cast<int>(page), layout.pages,
                              std::string(directionalCoefficientNames()[k]) + ".exr"),
          directionalPages[page].coefficients[k].radiance, {});
  // On one thread (--threads 1) they are written at the end, on this one.
  std::future<void> writingExrs =
      std::async(threads > 1 ? std::launch::async : std::launch::deferred, [&exrWrites] {
        for (const auto& write : exrWrites) write();
      });

  for (const Lightmap& page : lightmaps)
    look.lightmapPages.push_back(encodePng(page.radiance, toneMap));
  const BakedMesh baked = makeBakedMesh(mesh, interpolation, vertexRadiance,
                                        o.noLightmap ? nullptr : &layout, materialNames);
  if (!o.noLightmap) {
    // The scene's base colours stay in the glTF (its textures on TEXCOORD_0) under the lightmap.
    std::vector<std::vector<std::uint8_t>> pages = std::move(look.lightmapPages);
    look = bakedBaseColours(solution.scene, !baked.textureUvs.empty());
    look.lightmapPages = std::move(pages);
    summary["base_colour_images"] = look.images.size();
  }

  // Light groups: each layer's vertex values and lightmap pages, named by the group's file name.
  nlohmann::json groupsJson = nlohmann::json::array();
  for (size_t g = 0; g < solution.layers.size(); ++g) {
    const LightGroup& group = solution.layers[g].group;
    BakedLayer layer;
    layer.name = group.name;
    for (int v : baked.sourceVertex) layer.radiance.push_back(layerVertexRadiance[g][v]);
    nlohmann::json files = {groupFileName(group, "vertex_colors.ply")};
    if (!o.noLightmap)
      for (int page = 0; page < layout.pages; ++page) {
        layer.lightmapPages.push_back(encodePng(layerLightmaps[g][page].radiance, toneMap));
        layer.exrFiles.push_back(groupFileName(group, lightmapFileName(page, layout.pages, "exr")));
        files.push_back(layer.exrFiles.back());
        files.push_back(groupFileName(group, lightmapFileName(page, layout.pages, "png")));
      }
    nlohmann::json materials = nlohmann::json::array(), lights = nlohmann::json::array();
    for (int m : group.materials) materials.push_back(solution.scene.materials[m].name);
    for (size_t l : group.lights) lights.push_back(l);
    groupsJson.push_back({{"name", group.name},
                          {"emissive_materials", materials},
                          {"lights", lights},
                          {"glb_attribute", "_LIGHT_GROUP_" + std::to_string(g)},
                          {"files", files}});
    look.layers.push_back(std::move(layer));
  }
  if (!solution.layers.empty()) {
    summary["light_groups"] = groupsJson;
    logInfo("light groups: " + std::to_string(solution.layers.size()) +
            " layers (group_NAME_* files; they sum to the whole)");
  }

  std::vector<std::unique_ptr<AtomicFile>> files;
  auto open = [&](const std::string& name, bool binary) -> std::ostream& {
    files.push_back(std::make_unique<AtomicFile>((dir / name).string(), binary));
    return files.back()->stream();
  };
  writeVertexColorsPly(open("vertex_colors.ply", true), interpolation, mesh, vertexRadiance,
                       toneMap);
  writeBakedGlb(open("scene_baked.glb", true), baked, look, toneMap, o.content);
  std::vector<std::string> pngNames;
  for (int page = 0; page < static_cast<int>(lightmaps.size()); ++page) {
    const std::vector<std::uint8_t>& png = look.lightmapPages[page];
    pngNames.push_back(lightmapFileName(page, layout.pages, "png"));
    open(pngNames.back(), true)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  }
  for (size_t g = 0; g < solution.layers.size(); ++g) {
    const LightGroup& group = solution.layers[g].group;
    writeVertexColorsPly(open(groupFileName(group, "vertex_colors.ply"), true), interpolation, mesh,
                         layerVertexRadiance[g], toneMap);
    for (size_t page = 0; page < look.layers[g].lightmapPages.size(); ++page) {
      const std::vector<std::uint8_t>& png = look.layers[g].lightmapPages[page];
      open(groupFileName(group, lightmapFileName(static_cast<int>(page), layout.pages, "png")),
           true)
          .write(reinterpret_cast<const char*>(png.data()),
                 static_cast<std::streamsize>(png.size()));
    }
  }
  for (size_t page = 0; page < directionalPages.size(); ++page) {
    const std::vector<std::uint8_t> png = encodePng(directionalPages[page].direction, ToneMap{1});
    open(directionalFileName(static_cast<int>(page), layout.pages, "direction.png"), true)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  }
  if (!o.noLightmap) {
    std::ostream& obj = open("scene_baked.obj", false);
    writeBakedObj(obj, open("scene_baked.mtl", false), baked, "scene_baked.mtl", pngNames);
  }
  summary["export_seconds"] = since(start);
  open("bake.json", false) << summary.dump(2) << "\n";
  writingExrs.get();  // rethrows a failed write
  std::vector<AtomicFile*> set;
  for (auto& f : files) set.push_back(f.get());
  std::vector<AtomicPath*> exrSet;
  for (auto& f : exrFiles) exrSet.push_back(f.get());
  commitAll(set, exrSet);
  logInfo("baked " + o.solve.scenePath + " into " + o.solve.outputDir + " in " +
          std::to_string(since(start)) + " s after the solve");
}

}  // namespace

void registerBakeCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* bake =
      app.add_subcommand("bake", "Solve, then bake a lightmap atlas and glTF/OBJ/PLY exports");
  bake->add_option("scene", o->solve.scenePath,
                   std::string(kSceneFileHelp) + "; materials from its MTL or glTF")
      ->required();
  bake->add_option("--out", o->solve.outputDir, "Output directory (created if missing)")
      ->required();
  addSolveOptions(*bake, o->solve);
  auto* texel = bake->add_option("--texel-size", o->texelSize,
                                 "Lightmap texel size in scene units (pages grow to fit)")
                    ->check(CLI::PositiveNumber);
  bake->add_option(
          "--texel-density", o->texelDensity,
          "Lightmap texels per scene unit (default: " + formatNumber(kDefaultLightmapTexels) +
              " texels over the scene's surface); more pages when one does not hold them")
      ->check(CLI::PositiveNumber)
      ->excludes(texel);
  bake->add_option("--lightmap-size", o->lightmapSize,
                   "Alone: the side of one square lightmap page, at the densest texels that fit; "
                   "with --texel-density/--texel-size: the largest page side (default " +
                       std::to_string(kDefaultMaxLightmapPage) + ")")
      ->check(CLI::Range(8, 16384));
  bake->add_option("--padding", o->padding,
                   "Empty texels around each chart, each side (>= --dilation)")
      ->default_val(o->padding)
      ->check(CLI::Range(1, 64));
  bake->add_option("--dilation", o->dilation,
                   "Rings of texels filled around each chart (default: --padding)")
      ->check(CLI::Range(0, 64));
  addGatherOptions(*bake, o->gather, "texel (over its footprint, for sharp shadows)");
  auto* angle = bake->add_option("--chart-angle", o->chartAngle,
                                 "Largest normal angle within one chart, degrees")
                    ->default_val(o->chartAngle)
                    ->check(CLI::Range(0.0, 89.0));
  auto* noLightmap =
      bake->add_flag("--no-lightmap,--vertex-colors-only", o->noLightmap,
                     "Vertex colours only: vertex_colors.ply and an unlit scene_baked.glb");
  bake->add_flag("--use-scene-uvs", o->sceneUvs,
                 "Bake into the scene's own texture coordinates (every face needs 'vt', in [0, 1], "
                 "without overlaps) instead of generating lightmap UVs; charts are its UV islands")
      ->excludes(angle)
      ->excludes(noLightmap);
  o->exposure.add(*bake,
                  "Exposure of the 8-bit outputs (lightmap.png, vertex colours, the glTF): "
                  "display = clamp(exposure × radiance); default: the 99th percentile of the lit "
                  "surfaces' radiance maps to 1 (emitters excluded)");
  addChoiceOption(*bake, "--lightmap-content", o->content, lightmapContentTable(),
                  "What the lightmap holds: radiance (outgoing, textures included: display as "
                  "is) or irradiance (incident light / pi without the surface's albedo, for "
                  "engines that multiply it by the base colour; 0 where the reflectance is 0)");
  bake->add_flag("--light-groups", o->solve.lightGroups,
                 "One layer per light group (each emissive material; each light, or the lights "
                 "file's \"group\"; --sky, --sun): group_NAME_lightmap.exr/.png and "
                 "group_NAME_vertex_colors.ply beside the whole, and _LIGHT_GROUP_i in the glb, "
                 "so an engine can dim or recolour each group without a re-bake");
  bake->add_flag("--directional", o->directional,
                 "Directional lightmaps for normal-mapped surfaces: per texel the L1 spherical "
                 "harmonics of the incident light (lightmap_sh_L0/L1x/L1y/L1z.exr, world axes, "
                 "W/m^2) and lightmap_direction.png; see docs/baking.md");
  bake->add_option("--directional-rays", o->directionalRays,
                   "Hemisphere rays per texel of --directional")
      ->default_val(o->directionalRays)
      ->check(CLI::Range(1, 65536));
  bake->add_option("--solution", o->solutionDir,
                   "Reuse the solution `radiosity solve` wrote into this directory (same scene and "
                   "solve options) instead of solving");
  addCommonFlags(*bake);
  bake->callback([&run, bake, o] { run = [bake, o] { runBake(*bake, *o); }; });
}

}  // namespace rad
