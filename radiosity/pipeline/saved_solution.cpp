#include "radiosity/pipeline/saved_solution.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/core/errors.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/pipeline/fingerprint.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/problem_setup.h"

namespace rad {
namespace {

constexpr const char* kFormat = "radiosity saved solution 1";

}  // namespace

std::string solutionFingerprint(const Scene& scene, const SolveOptions& o) {
  Fingerprint f;
  f.add(std::string(kFormat));
  addGeometry(f, scene);
  f.add(scene.materials.size());
  for (const Material& m : scene.materials) {
    f.add(m.name);
    f.add(m.diffuse);
    f.add(m.emission);
    f.add(m.specular);
    f.add(m.transmittance);
    f.add(m.ior);
    f.add(static_cast<int>(m.kind));
    f.add(m.diffuseTexture);
    f.add(m.emissionTexture);
  }
  f.add(scene.textures.size());
  for (const Texture& t : scene.textures) {
    f.add(t.width);
    f.add(t.height);
    for (float v : t.rgba) f.add(v);
  }
  f.add(scene.lights.size());
  for (const Light& l : scene.lights) {
    f.add(static_cast<int>(l.type));
    for (const Eigen::Vector3d* v : {&l.position, &l.direction, &l.up})
      for (int k = 0; k < 3; ++k) f.add((*v)[k]);
    f.add(l.intensity);
    f.add(l.irradiance);
    f.add(l.radiance);
    f.add(l.cosOuter);
    f.add(l.cosInner);
    f.add(l.angularDiameterDegrees);
    f.add(static_cast<int>(l.skyModel));
    f.add(l.map ? l.map->width() : 0);
    f.add(l.map ? l.map->height() : 0);
    if (l.map)
      for (const Rgb& t : l.map->texels()) f.add(t);
  }
  f.add(static_cast<int>(o.solver));
  f.add(o.raysPerElement);
  f.add(o.maxArea);
  f.add(o.targetElements);
  f.add(o.elementSize);
  f.add(o.seed);
  f.add(o.tolerance);
  f.add(o.maxIterations);
  f.add(o.bounces);
  f.add(static_cast<int>(o.formFactors));
  f.add(o.patchArea);
  f.add(o.shadowRays);
  f.add(o.receiverPoints);
  if (o.solver == SolverKind::Hierarchical) f.add(o.linkEpsilon);
  return f.hex();
}

bool solutionIsReusable(const SolveOptions& options) {
  return !(options.refineThreshold > 0) && !options.keepBounceTerms && !options.lightGroups;
}

std::optional<SolveResult> loadSavedSolution(const std::string& dir, const Scene& scene,
                                             const SolveOptions& options, std::string& whyNot) {
  const std::filesystem::path base(dir);
  const std::string jsonPath = (base / kSolutionJson).string();
  if (!solutionIsReusable(options)) {
    whyNot = options.keepBounceTerms ? "--bounces-separate: the Jacobi terms are not saved"
             : options.lightGroups   ? "--light-groups: a saved solution holds no layers"
                                     : "adaptive refinement: the mesh depends on the solve";
    return std::nullopt;
  }
  if (!std::filesystem::exists(jsonPath)) {
    whyNot = "no saved solution in " + dir;
    return std::nullopt;
  }
  nlohmann::json meta;
  {
    std::ifstream in(jsonPath);
    try {
      meta = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
      throw InputError(jsonPath, 0, "unreadable saved solution: " + std::string(e.what()));
    }
  }
  if (!meta.is_object() || meta.value("format", "") != kFormat || !meta.contains("fingerprint") ||
      !meta["fingerprint"].is_string())
    throw InputError(jsonPath, 0,
                     std::string("not a saved solution (expected \"format\": \"") + kFormat +
                         "\" and a \"fingerprint\"); delete it to solve again");
  if (meta["fingerprint"].get<std::string>() != solutionFingerprint(scene, options)) {
    whyNot = "the saved solution was made from another scene or other solve options";
    return std::nullopt;
  }
  const auto csvName = meta.value("elements_file", std::string(kSolutionCsv));
  if (csvName.empty() || csvName.find('/') != std::string::npos || csvName == "..")
    throw InputError(jsonPath, 0, "\"elements_file\" must name a file beside solution.json");
  const std::string csvPath = (base / csvName).string();

  SolveResult result;
  MeshedScene meshed = meshScene(scene, options);
  result.solution.mesh = std::move(meshed.mesh);
  const PatchMesh& mesh = *result.solution.mesh;
  const int count = mesh.elementCount();
  result.solution.radiosity.assign(count, Rgb());
  const std::vector<ElementsCsvRow> rows = readElementsCsv(csvPath);
  int lineNumber = 1;
  // Centroids are written with 17 significant digits: the re-meshed scene must give them back
  // to rounding, or the file belongs to another mesh.
  const double tolerance = 1e-9 * std::sqrt(mesh.totalArea());
  int element = 0;
  for (const ElementsCsvRow& row : rows) {
    lineNumber = row.line;
    if (element >= count)
      throw InputError(
          csvPath, lineNumber,
          "more elements than the re-meshed scene has (" + std::to_string(count) + ")");
    if (row.element != element)
      throw InputError(csvPath, lineNumber, "expected element " + std::to_string(element));
    if ((row.centroid - mesh.centroid(element)).norm() > tolerance)
      throw InputError(csvPath, lineNumber,
                       "element " + std::to_string(element) +
                           " lies elsewhere than in the re-meshed scene; delete the saved "
                           "solution to solve again");
    if (row.radiosity.minComponent() < 0)
      throw InputError(csvPath, lineNumber, "negative radiosity");
    result.solution.radiosity[element++] = row.radiosity;
  }
  if (element != count)
    throw InputError(csvPath, lineNumber,
                     "the saved solution has " + std::to_string(element) +
                         " elements, the re-meshed scene " + std::to_string(count));
  result.solution.scene = scene;
  // The exposed areas the solve had: the outputs weigh vertex values by them.
  const RayCaster rays(mesh, result.solution.scene);
  const ElementExposure exposure = solveExposure(options, mesh, rays);
  result.solution.problem = makeProblem(scene, mesh, &exposure);
  result.report.solverName = meta.value("solver", std::string("saved")) + " (reused)";
  result.report.converged = meta.value("converged", false);
  result.report.maxArea = meshed.maxArea;
  result.report.elementSize = meshed.sizing.edge;
  result.report.elementSizeRule = elementSizeRuleName(meshed.sizing.rule);
  result.report.reusedSavedSolution = true;
  return result;
}

void writeSavedSolution(AtomicFile& csv, AtomicFile& json, const SolveResult& result,
                        const SolveOptions& options) {
  writeElementsCsv(csv.stream(), *result.solution.mesh, result.solution.radiosity);
  writeSavedSolutionJson(json, kSolutionCsv, result, options);
}

void writeSavedSolutionJson(AtomicFile& json, const std::string& elementsFile,
                            const SolveResult& result, const SolveOptions& options) {
  const nlohmann::json meta = {
      {"format", kFormat},
      {"fingerprint", solutionFingerprint(result.solution.scene, options)},
      {"scene", options.scenePath},
      {"elements_file", elementsFile},
      {"elements", result.solution.mesh->elementCount()},
      {"solver", result.report.solverName},
      {"converged", result.report.converged},
      {"seed", options.seed},
      {"comment", "B per element in " + elementsFile +
                      " (W/m^2); render, bake and view with --solution on this directory (or "
                      "--out, for render) reuse it for the same scene and solve options"},
  };
  json.stream() << meta.dump(2) << "\n";
}

}  // namespace rad
