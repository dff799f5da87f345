#include "radiosity/pipeline/saved_solution.h"

#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/pipeline/fingerprint.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/scene/lights.h"
#include "radiosity/scene/scene_overrides.h"

namespace rad {
namespace {

constexpr const char* kFormat = "radiosity saved solution 1";

nlohmann::json rgbJson(const Rgb& c) { return {c.r, c.g, c.b}; }

// relight's overrides, kept in solution.json so that the relit solution is recognised: the scene
// it belongs to is the scene's files with these applied.
nlohmann::json relitJson(const SolveReport& report, const Scene& scene) {
  nlohmann::json materials = nlohmann::json::array();
  for (const auto& [index, change] : report.relitMaterials) {
    nlohmann::json m = {{"index", index}, {"name", scene.materials[index].name}};
    if (change.diffuse) m["diffuse"] = rgbJson(*change.diffuse);
    if (change.emission) m["emission"] = rgbJson(*change.emission);
    materials.push_back(m);
  }
  nlohmann::json scales = nlohmann::json::array();
  for (const Rgb& s : report.relitLightScale) scales.push_back(rgbJson(s));
  return {{"kept_factors", report.relitFrom},
          {"materials", materials},
          {"light_scale", scales},
          {"comment",
           "relight's overrides: the scene files with these applied are the scene this solution "
           "is for"}};
}

// `scene` with a relit entry's overrides applied; nothing (and `whyNot`) when they name
// materials or lights the scene does not have. InputError naming the file and the JSON pointer
// when the entry is malformed.
std::optional<Scene> relitScene(const nlohmann::json& relit, const Scene& scene,
                                const std::string& jsonPath, std::string& whyNot) {
  auto fail = [&](const std::string& pointer, const std::string& what) {
    throw InputError(jsonPath, 0, "/relit" + pointer + ": " + what);
  };
  auto rgbAt = [&](const nlohmann::json& j, const std::string& pointer) {
    if (!j.is_array() || j.size() != 3) fail(pointer, "expected [r, g, b]");
    Rgb c;
    for (int k = 0; k < 3; ++k) {
      if (!j[k].is_number()) fail(pointer + "/" + std::to_string(k), "expected a number");
      c[k] = j[k].get<double>();
    }
    if (!c.isFinite() || c.minComponent() < 0) fail(pointer, "expected finite values >= 0");
    return c;
  };
  if (!relit.is_object()) fail("", "expected an object");
  const auto materials = relit.find("materials");
  const auto scales = relit.find("light_scale");
  if (materials == relit.end() || !materials->is_array()) fail("/materials", "expected an array");
  if (scales == relit.end() || !scales->is_array()) fail("/light_scale", "expected an array");
  Scene changed = scene;
  for (size_t i = 0; i < materials->size(); ++i) {
    const nlohmann::json& m = (*materials)[i];
    const std::string at = "/materials/" + std::to_string(i);
    if (!m.is_object() || !m.contains("index") || !m["index"].is_number_integer() ||
        !m.contains("name") || !m["name"].is_string())
      fail(at, "expected {\"index\": i, \"name\": \"...\", ...}");
    const auto index = m["index"].get<int64_t>();
    if (index < 0 || index >= static_cast<int64_t>(changed.materials.size()) ||
        changed.materials[static_cast<size_t>(index)].name != m["name"].get<std::string>()) {
      whyNot = "the saved solution was relit with a material the scene does not have (" +
               m["name"].get<std::string>() + ")";
      return std::nullopt;
    }
    MaterialOverride change;
    if (m.contains("diffuse")) change.diffuse = rgbAt(m["diffuse"], at + "/diffuse");
    if (m.contains("emission")) change.emission = rgbAt(m["emission"], at + "/emission");
    applyMaterialOverride(changed.materials[static_cast<size_t>(index)], change);
  }
  if (scales->size() != changed.lights.size()) {
    whyNot = "the saved solution was relit for " + std::to_string(scales->size()) +
             " light(s), the scene has " + std::to_string(changed.lights.size());
    return std::nullopt;
  }
  for (size_t l = 0; l < scales->size(); ++l)
    changed.lights[l] =
        scaledLight(changed.lights[l], rgbAt((*scales)[l], "/light_scale/" + std::to_string(l)));
  return changed;
}

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
  addTextures(f, scene);
  addLights(f, scene.lights);
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
  // The member `key`, which must have the type of `fallback`, or `fallback` where it is absent.
  auto member = [&](const char* key, const nlohmann::json& fallback) {
    const auto it = meta.find(key);
    if (it == meta.end()) return fallback;
    if (it->type() != fallback.type())
      throw InputError(jsonPath, 0,
                       std::string("/") + key + ": expected a " + fallback.type_name());
    return *it;
  };
  if (!meta.is_object() || !meta.contains("format") || meta["format"] != kFormat ||
      !meta.contains("fingerprint") || !meta["fingerprint"].is_string())
    throw InputError(jsonPath, 0,
                     std::string("not a saved solution (expected \"format\": \"") + kFormat +
                         "\" and a \"fingerprint\"); delete it to solve again");
  // A relit solution (radiosity relight) is for the scene with relight's overrides applied.
  std::optional<Scene> relit;
  if (meta.contains("relit")) {
    relit = relitScene(meta["relit"], scene, jsonPath, whyNot);
    if (!relit) return std::nullopt;
  }
  const Scene& solved = relit ? *relit : scene;
  if (meta["fingerprint"].get<std::string>() != solutionFingerprint(solved, options)) {
    whyNot = "the saved solution was made from another scene or other solve options";
    return std::nullopt;
  }
  const auto csvName = member("elements_file", kSolutionCsv).get<std::string>();
  if (csvName.empty() || csvName.find('/') != std::string::npos || csvName == "..")
    throw InputError(jsonPath, 0, "\"elements_file\" must name a file beside solution.json");
  const std::string csvPath = (base / csvName).string();

  SolveResult result;
  // The CSV is read on another thread while the scene is meshed (the two take about as long),
  // unless --threads 1 asked for one thread.
  const bool oneThread =
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) == 1;
  std::future<ElementsCsv> reading =
      std::async(oneThread ? std::launch::deferred : std::launch::async,
                 [&csvPath] { return readElementsCsv(csvPath); });
  MeshedScene meshed = meshScene(solved, options);
  result.solution.mesh = std::move(meshed.mesh);
  const PatchMesh& mesh = *result.solution.mesh;
  const int count = mesh.elementCount();
  result.solution.radiosity.assign(count, Rgb());
  const ElementsCsv csv = reading.get();
  const std::vector<ElementsCsvRow>& rows = csv.rows;
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
  // E_d as the solve computed it, where the file keeps it (the Ed columns); left empty otherwise
  // (solveOrReuse refuses such a solution where the split needs E_d).
  if (csv.hasDirectIrradiance) {
    result.solution.directIrradiance.resize(count);
    for (int e = 0; e < count; ++e) result.solution.directIrradiance[e] = rows[e].directIrradiance;
  }
  result.solution.scene = relit ? std::move(*relit) : scene;
  // The exposed areas the solve had: the outputs weigh vertex values by them. Read back where the
  // file keeps the buried cells; found again by probe rays (a BVH and 0.3 s on a large scene)
  // in a file written before it kept them.
  std::shared_ptr<const ElementExposure> exposure;
  if (csv.hasBuriedCells) {
    std::vector<uint64_t> buried(count);
    for (int e = 0; e < count; ++e) buried[e] = rows[e].buriedCells;
    exposure = std::make_shared<const ElementExposure>(mesh, std::move(buried));
  } else {
    const RayCaster rays(mesh, result.solution.scene);
    exposure = std::make_shared<const ElementExposure>(solveExposure(options, mesh, rays));
  }
  result.solution.problem = makeProblem(result.solution.scene, mesh, exposure.get());
  result.solution.exposure = std::move(exposure);
  result.report.solverName = member("solver", "saved").get<std::string>() + " (reused)";
  result.report.converged = member("converged", false).get<bool>();
  result.report.maxArea = meshed.maxArea;
  result.report.elementSize = meshed.sizing.edge;
  result.report.elementSizeRule = elementSizeRuleName(meshed.sizing.rule);
  result.report.reusedSavedSolution = true;
  return result;
}

void writeSolutionElementsCsv(std::ostream& out, const Solution& solution) {
  const PatchMesh& mesh = *solution.mesh;
  const std::vector<Rgb>& direct = solution.directIrradiance;
  if (!direct.empty()) RAD_CHECK_EQ(direct.size(), mesh.elementCount());
  const std::vector<Rgb>* directColumns = direct.empty() ? nullptr : &direct;
  if (!solution.exposure)
    return writeElementsCsv(out, mesh, solution.radiosity, nullptr, directColumns);
  const std::vector<uint64_t> buried = solution.exposure->allBuriedCells(mesh.elementCount());
  writeElementsCsv(out, mesh, solution.radiosity, &buried, directColumns);
}

void writeSavedSolution(AtomicFile& csv, AtomicFile& json, const SolveResult& result,
                        const SolveOptions& options) {
  writeSolutionElementsCsv(csv.stream(), result.solution);
  writeSavedSolutionJson(json, kSolutionCsv, result, options);
}

void writeSavedSolutionJson(AtomicFile& json, const std::string& elementsFile,
                            const SolveResult& result, const SolveOptions& options) {
  nlohmann::json meta = {
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
  if (!result.report.relitFrom.empty())
    meta["relit"] = relitJson(result.report, result.solution.scene);
  json.stream() << meta.dump(2) << "\n";
}

}  // namespace rad
