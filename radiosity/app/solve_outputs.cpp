// Writing a finished solve: elements.csv, vertex_colors.ply and summary.json.
#include "radiosity/app/solve_outputs.h"

#include <tbb/parallel_invoke.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "meshing/vertex_interpolation.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/log.h"
#include "radiosity/core/peak_memory.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/display_radiance.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/output/tone_map.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/pipeline/solution_tone_map.h"
#ifdef RADIOSITY_HAS_VIEWER
#include "viewer/solution_vtp.h"
#endif

namespace rad {
namespace {
#ifdef RADIOSITY_HAS_VIEWER
constexpr bool kWritesVtp = true;
#else
constexpr bool kWritesVtp = false;
#endif

// summary.json's "scene": the scene, its mesh, the element size and the buried parts.
nlohmann::json sceneJson(const SolveOptions& options, const SolveResult& result) {
  using nlohmann::json;
  const Solution& s = result.solution;
  const SolveReport& r = result.report;
  const PatchMesh& mesh = *s.mesh;
  int emitterElements = 0;
  for (const Rgb& e : s.problem.emission) emitterElements += e.maxComponent() > 0;
  int backSideElements = 0;  // elements of the back copies of two-sided polygons
  for (int e = 0; e < mesh.elementCount(); ++e)
    backSideElements += s.scene.polygons[static_cast<std::size_t>(mesh.patch(e))].backSideOf >= 0;
  json materials = json::array();
  for (const Material& m : s.scene.materials) materials.push_back(m.name);
  return {{"file", options.scenePath},
          {"polygons", s.scene.polygons.size()},
          {"triangles", mesh.inputTriangleCount()},
          {"patches", mesh.patchCount()},
          {"elements", mesh.elementCount()},
          {"back_side_polygons", s.scene.backSideCount()},
          {"back_side_elements", backSideElements},
          {"vertices", mesh.vertexCount()},
          {"emitters", s.scene.emitterCount()},
          {"emitter_elements", emitterElements},
          {"materials", materials},
          {"skipped_degenerate_faces", s.scene.skippedDegenerateFaces},
          {"texture_fallbacks", s.scene.textureFallbacks},
          {"total_area", mesh.totalArea()},
          {"max_element_area", r.maxArea},
          {"element_size", r.elementSize},
          {"element_size_rule", r.elementSizeRule},
          {"elements_before_refinement", r.elementsBeforeRefinement},
          {"refinement_passes", r.refinementPasses},
          {"buried",
           {{"partly", r.partlyBuried},
            {"fully", r.fullyBuried},
            {"area_fraction", r.buriedAreaFraction},
            {"probe_rays", r.exposureProbeRays},
            {"note",
             "parts of elements enclosed by one-sided geometry (under a box standing on them): "
             "they neither receive nor shoot, and B is over the exposed area"}}}};
}

// summary.json's "form_factors": what was cast, and how fast.
nlohmann::json formFactorsJson(const SolveOptions& options, const SolveReport& r) {
  using nlohmann::json;
  const bool hemisphere = options.formFactors == FormFactorMethod::Hemisphere;
  const double rayTime = r.times.formFactors;
  return {{"method", formFactorMethodName(options.formFactors)},
          {"shooters", r.shooters},
          {"rays_per_element", hemisphere ? json(options.raysPerElement) : json()},
          {"shadow_rays", hemisphere ? json() : json(options.shadowRays)},
          {"receiver_points", hemisphere ? json() : json(options.receiverPoints)},
          {"rows_computed", r.rowsComputed},
          {"rays_cast", r.raysCast},
          {"specular_rays", r.specularRays},
          {"rays_per_second", rayTime > 0 ? r.raysCast / rayTime : 0.0},
          {"seed", options.seed}};
}

// summary.json's "lights": the lights by type and their first shot's rays.
nlohmann::json lightsJson(const Scene& scene, const SolveReport& r) {
  const auto count = [&scene](const char* type) {
    int n = 0;
    for (const Light& light : scene.lights) n += lightTypeName(light.type) == type;
    return n;
  };
  return {{"point", count("point")},
          {"spot", count("spot")},
          {"directional", count("directional")},
          {"sky", count("sky")},
          {"environment", count("environment")},
          {"direct_light_rays", r.directLightRays},
          {"note",
           "the first shot of these lights at each element's receiver points enters the solve "
           "as emission: emitted_power includes its reflected part"}};
}

// summary.json's "hierarchy" (--solver hierarchical; null otherwise).
nlohmann::json hierarchyJson(const SolveOptions& options, const SolveReport& r,
                             const PatchMesh& mesh) {
  using nlohmann::json;
  return r.hierarchy.nodes == 0
             ? json()
             : json{{"link_epsilon", options.linkEpsilon},
                    {"nodes", r.hierarchy.nodes},
                    {"clusters", r.hierarchy.clusters},
                    {"depth", r.hierarchy.depth},
                    {"links", r.hierarchy.links},
                    {"receivers", r.hierarchy.receivers},
                    {"link_passes", r.hierarchy.linkPasses},
                    {"links_split_by_refinement", r.hierarchy.linksRefined},
                    {"bytes",
                     {{"tree", r.hierarchy.treeBytes},
                      {"links", r.hierarchy.linkBytes},
                      {"solver", r.hierarchy.solverBytes}}},
                    {"bytes_per_element",
                     static_cast<double>(r.hierarchy.treeBytes + r.hierarchy.linkBytes +
                                         r.hierarchy.solverBytes) /
                         mesh.elementCount()},
                    {"bytes_per_link",
                     r.hierarchy.links > 0
                         ? static_cast<double>(r.hierarchy.linkBytes) / r.hierarchy.links
                         : 0.0},
                    {"peak_memory_bytes", peakMemoryBytes()},
                    {"note",
                     "links between nodes of a tree over the elements (clusters above the input "
                     "patches); bytes are the tree's, the links' and the solver's own, "
                     "peak_memory_bytes the whole process's"}};
}

// summary.json's "update" (radiosity update; null otherwise).
nlohmann::json updateJson(const SolveReport& r) {
  using nlohmann::json;
  return r.update.keptFactors.empty()
             ? json()
             : json{{"kept_factors", r.update.keptFactors},
                    {"elements_moved_or_added", r.update.moved},
                    {"kept_elements_moved_or_removed", r.update.removed},
                    {"rows_reused", r.update.rowsReused},
                    {"rows_updated_ray_by_ray", r.update.rowsUpdated},
                    {"rays_changed", r.update.raysChanged},
                    {"rays_tested", r.update.raysTested},
                    {"rays_of_kept_rows", r.update.raysOfKeptRows},
                    {"rows_cast_again", r.rowsComputed},
                    {"rows_with_other_exposure_or_budget", r.update.rowsOtherChange},
                    {"direct_light_kept", r.update.directLightKept},
                    {"buried_cells_kept", r.update.buriedCellsKept},
                    {"note",
                     "a kept row of an element that stayed put is reused; the rays of it "
                     "that meet the edited geometry's old or new place before their first "
                     "hit are cast again and their hits exchanged; an element's direct "
                     "light from a light is kept where none of its shadow rays to it can "
                     "meet the edit (direct_light_kept counts element-light pairs), and "
                     "its buried cells where none of its probe rays can "
                     "(buried_cells_kept counts elements)"}};
}

nlohmann::json summaryJson(const SolveOptions& options, const SolveResult& result,
                           double exposure) {
  using nlohmann::json;
  const Solution& s = result.solution;
  const SolveReport& r = result.report;
  json skipped = json::array();
  for (const SkipNote& note : r.skipped)
    skipped.push_back({{"what", note.what}, {"why", note.why}});
  return {
      {"scene", sceneJson(options, result)},
      {"form_factors", formFactorsJson(options, r)},
      {"lights", lightsJson(s.scene, r)},
      {"solver",
       {{"name", r.solverName},
        {"iterations", r.iterations},
        {"measure", r.progressMeasure},
        {"final", r.finalProgress},
        {"tolerance", options.bounces >= 0 ? 0.0 : options.tolerance},
        {"bounces", options.bounces >= 0 ? nlohmann::json(options.bounces) : nlohmann::json()},
        {"converged", r.converged},
        {"stopped_by", stopReasonName(r.stoppedBy)},
        {"emitted_power", s.problem.emittedPower()}}},
      {"threads", r.threads},
      {"time_seconds",
       {{"load", r.times.load},
        {"mesh", r.times.mesh},
        {"bvh", r.times.bvh},
        {"form_factors", r.times.formFactors},
        {"solve", r.times.solve},
        {"output", r.times.output},
        {"total", r.times.total}}},
      {"units",
       {{"B", "radiosity, W/m^2 (scene units in metres)"},
        {"L", "outgoing radiance B/pi, W/(m^2 sr)"}}},
      {"tone_map", {{"exposure", exposure}, {"operator", "clamp(exposure*L) then sRGB OETF"}}},
      {"skipped", skipped},
      {"relight", r.relitFrom.empty()
                      ? json()
                      : json{{"kept_factors", r.relitFrom},
                             {"rays_cast", r.raysCast + r.directLightRays + r.exposureProbeRays},
                             {"note", "solved again from the kept factors: no ray cast"}}},
      {"hierarchy", hierarchyJson(options, r, *s.mesh)},
      {"update", updateJson(r)},
  };
}

// Writes the three files under temporary names, then renames them all.
void writeFiles(const SolveOptions& options, SolveResult& result,
                std::chrono::steady_clock::time_point start, const std::vector<ProbeSh>* probes) {
  const std::filesystem::path dir(options.outputDir);
  const Solution& solution = result.solution;
  const PatchMesh& mesh = *solution.mesh;

  // The large files are independent: written side by side (on a large scene each takes a good
  // part of a second; factors.bin, kept for relight and update, is hundreds of megabytes).
  const ToneMap toneMap = solutionToneMap(solution);
  AtomicFile csv((dir / "elements.csv").string());
  AtomicFile ply((dir / "vertex_colors.ply").string(), /*binary=*/true);
  std::vector<AtomicFile*> files = {&csv, &ply};
  // What relight reuses (solve --keep-factors).
  std::unique_ptr<AtomicFile> factors;
  if (result.kept) {
    factors = std::make_unique<AtomicFile>((dir / kKeptFactorsFile).string(), /*binary=*/true);
    files.push_back(factors.get());
  }
  const auto writeCsv = [&] { writeSolutionElementsCsv(csv.stream(), solution); };
  const auto writePly = [&] {
    const VertexInterpolation interpolation(mesh, solution.problem.area);  // exposed areas
    const std::vector<Rgb> vertexRadiance =
        interpolateVertexRadiance(interpolation, solution.radiosity, solution.pointRadiosity);
    writeVertexColorsPly(ply.stream(), interpolation, mesh, vertexRadiance, toneMap);
  };
  const auto writeFactors = [&] {
    if (factors) writeKeptFactors(factors->stream(), *result.kept);
  };
#ifdef RADIOSITY_HAS_VIEWER
  // ParaView-ready solution.vtp (the VTK viewer's format), committed with the others below.
  AtomicFile vtp((dir / "solution.vtp").string(), /*binary=*/true);
  files.push_back(&vtp);
  tbb::parallel_invoke(writeCsv, writePly, writeFactors, [&] {
    writeSolutionVtp(vtp.stream(), mesh, solution.radiosity, solution.unshot, toneMap,
                     options.scenePath);
  });
#else
  tbb::parallel_invoke(writeCsv, writePly, writeFactors);
#endif
  // What render, bake and view --solution need to reuse elements.csv.
  std::unique_ptr<AtomicFile> saved;
  if (solutionIsReusable(options)) {
    saved = std::make_unique<AtomicFile>((dir / kSolutionJson).string());
    writeSavedSolutionJson(*saved, "elements.csv", result, options);
    files.push_back(saved.get());
  }

  // The light probes of `solve --probes`.
  std::unique_ptr<AtomicFile> probesJson, probesBin;
  if (probes) {
    probesJson = std::make_unique<AtomicFile>((dir / "probes.json").string());
    writeProbesJson(probesJson->stream(), *probes);
    probesBin = std::make_unique<AtomicFile>((dir / "probes.bin").string(), /*binary=*/true);
    writeProbesBinary(probesBin->stream(), *probes);
    files.push_back(probesJson.get());
    files.push_back(probesBin.get());
  }

  result.report.times.output = secondsSince(start);
  result.report.times.total += result.report.times.output;
  AtomicFile summary((dir / "summary.json").string());
  summary.stream() << summaryJson(options, result, toneMap.exposure).dump(2) << "\n";

  // Only once every file is complete on disk do they take their final names.
  files.push_back(&summary);
  commitAll(files);
}

void writeOutputs(const SolveOptions& options, SolveResult& result,
                  const std::vector<ProbeSh>* probes) {
  const auto start = std::chrono::steady_clock::now();
  const bool createdDirectory = ensureDirectory(options.outputDir);
  try {
    writeFiles(options, result, start, probes);
  } catch (...) {
    // Nothing of this run may remain: not a file, not the directory it made.
    if (createdDirectory) {
      std::error_code ignored;
      std::filesystem::remove_all(options.outputDir, ignored);
    }
    throw;
  }
  logInfo("wrote the solution files (elements.csv, vertex_colors.ply, summary.json" +
          std::string(solutionIsReusable(options) ? ", solution.json" : "") +
          std::string(result.kept ? ", factors.bin" : "") +
          std::string(kWritesVtp ? ", solution.vtp" : "") +
          std::string(probes ? ", probes.json, probes.bin" : "") + ") to " + options.outputDir);
}

}  // namespace

void writeSolveOutputs(const SolveOptions& options, SolveResult& result) {
  writeOutputs(options, result, nullptr);
}

void writeSolveOutputs(const SolveOptions& options, SolveResult& result,
                       const std::vector<ProbeSh>& probes) {
  writeOutputs(options, result, &probes);
}

}  // namespace rad
