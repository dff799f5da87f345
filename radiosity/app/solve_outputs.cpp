// Writing a finished solve: elements.csv, vertex_colors.ply and summary.json.
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "meshing/vertex_interpolation.h"
#include "radiosity/app/solve_job.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/log.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/output/tone_map.h"
#include "radiosity/output/vertex_colors_ply.h"
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

nlohmann::json summaryJson(const SolveOptions& options, const SolveResult& r, double exposure) {
  using nlohmann::json;
  const PatchMesh& mesh = *r.mesh;
  int emitterElements = 0;
  for (const Rgb& e : r.problem.emission) emitterElements += e.maxComponent() > 0;
  json skipped = json::array();
  for (const SkipNote& s : r.skipped) skipped.push_back({{"what", s.what}, {"why", s.why}});
  json materials = json::array();
  for (const Material& m : r.scene.materials) materials.push_back(m.name);

  const double rayTime = r.times.formFactors;
  return {
      {"scene",
       {{"file", options.scenePath},
        {"polygons", r.scene.polygons.size()},
        {"triangles", mesh.inputTriangleCount()},
        {"patches", mesh.patchCount()},
        {"elements", mesh.elementCount()},
        {"vertices", mesh.vertexCount()},
        {"emitters", r.scene.emitterCount()},
        {"emitter_elements", emitterElements},
        {"materials", materials},
        {"skipped_degenerate_faces", r.scene.skippedDegenerateFaces},
        {"total_area", mesh.totalArea()},
        {"max_element_area", r.maxArea},
        {"elements_before_refinement", r.elementsBeforeRefinement},
        {"refinement_passes", r.refinementPasses}}},
      {"form_factors",
       {{"method", r.formFactorMethod},
        {"shooters", r.shooters},
        {"rays_per_element", options.raysPerElement},
        {"rows_computed", r.rowsComputed},
        {"rays_cast", r.raysCast},
        {"specular_rays", r.specularRays},
        {"rays_per_second", rayTime > 0 ? r.raysCast / rayTime : 0.0},
        {"seed", options.seed}}},
      {"solver",
       {{"name", r.solverName},
        {"iterations", r.iterations},
        {"measure", r.progressMeasure},
        {"final", r.finalProgress},
        {"tolerance", options.bounces >= 0 ? 0.0 : options.tolerance},
        {"bounces", options.bounces >= 0 ? nlohmann::json(options.bounces) : nlohmann::json()},
        {"converged", r.converged},
        {"stopped_by", r.stoppedBy},
        {"emitted_power", r.problem.emittedPower()}}},
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
  };
}

// Writes the three files under temporary names, then renames them all.
void writeFiles(const SolveOptions& options, SolveResult& result,
                std::chrono::steady_clock::time_point start) {
  const std::filesystem::path dir(options.outputDir);
  const PatchMesh& mesh = *result.mesh;

  AtomicFile csv((dir / "elements.csv").string());
  writeElementsCsv(csv.stream(), mesh, result.radiosity);

  const VertexInterpolation interpolation(mesh);
  const std::vector<Rgb> vertexRadiance =
      interpolateVertexRadiance(interpolation, result.radiosity, result.pointRadiosity);
  std::vector<Rgb> elementRadiance(result.radiosity.size());
  for (size_t e = 0; e < elementRadiance.size(); ++e)
    elementRadiance[e] = result.radiosity[e] / M_PI;
  const ToneMap toneMap = ToneMap::autoExposure(elementRadiance, result.problem.area);
  AtomicFile ply((dir / "vertex_colors.ply").string(), /*binary=*/true);
  writeVertexColorsPly(ply.stream(), interpolation, mesh, vertexRadiance, toneMap);
  std::vector<AtomicFile*> files = {&csv, &ply};
#ifdef RADIOSITY_HAS_VIEWER
  // ParaView-ready solution.vtp (the VTK viewer's format), committed with the others below.
  std::vector<Rgb> unshot(result.radiosity.size());
  for (size_t e = 0; e < unshot.size(); ++e) {
    const Eigen::Vector3d u = mesh.unshot(static_cast<int>(e));
    unshot[e] = {u.x(), u.y(), u.z()};
  }
  AtomicFile vtp((dir / "solution.vtp").string(), /*binary=*/true);
  writeSolutionVtp(vtp.stream(), mesh, result.radiosity, unshot, toneMap, options.scenePath);
  files.push_back(&vtp);
#endif

  result.times.output =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.times.total += result.times.output;
  AtomicFile summary((dir / "summary.json").string());
  summary.stream() << summaryJson(options, result, toneMap.exposure).dump(2) << "\n";

  // Only once every file is complete on disk do they take their final names.
  files.push_back(&summary);
  commitAll(files);
}

}  // namespace

void writeSolveOutputs(const SolveOptions& options, SolveResult& result) {
  const auto start = std::chrono::steady_clock::now();
  const bool createdDirectory = ensureDirectory(options.outputDir);
  try {
    writeFiles(options, result, start);
  } catch (...) {
    // Nothing of this run may remain: not a file, not the directory it made.
    if (createdDirectory) {
      std::error_code ignored;
      std::filesystem::remove_all(options.outputDir, ignored);
    }
    throw;
  }
  logInfo("wrote the solution files (elements.csv, vertex_colors.ply, summary.json" +
          std::string(kWritesVtp ? ", solution.vtp" : "") + ") to " + options.outputDir);
}

}  // namespace rad
