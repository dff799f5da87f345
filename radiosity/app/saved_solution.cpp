#include "radiosity/app/saved_solution.h"

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
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

constexpr const char* kFormat = "radiosity saved solution 1";

// FNV-1a over the bytes of everything fed to it.
class Fingerprint {
 public:
  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    addBytes(&value, sizeof(T));
  }
  void add(const std::string& s) {
    add(s.size());
    addBytes(s.data(), s.size());
  }
  void add(const Rgb& c) {
    add(c.r);
    add(c.g);
    add(c.b);
  }
  std::string hex() const {
    std::ostringstream out;
    out << std::hex << hash_;
    return out.str();
  }

 private:
  void addBytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
  }
  uint64_t hash_ = 0xcbf29ce484222325ull;
};

// The mesh solveScene() builds before any form factor (uniform meshing only).
std::unique_ptr<PatchMesh> remesh(const Scene& scene, const SolveOptions& options) {
  auto mesh = std::make_unique<PatchMesh>(buildPatchMesh(scene));
  const double maxArea =
      options.maxArea > 0 ? options.maxArea : mesh->totalArea() / options.targetElements;
  if (options.formFactors == FormFactorMethod::Analytic) {
    mesh->subdivideUniform(options.patchArea > 0 ? options.patchArea : 8 * maxArea);
    mesh->markShooters();
  }
  mesh->subdivideUniform(maxArea);
  return mesh;
}

}  // namespace

std::string solutionFingerprint(const Scene& scene, const SolveOptions& o) {
  Fingerprint f;
  f.add(std::string(kFormat));
  f.add(scene.positions.size());
  for (const Eigen::Vector3d& p : scene.positions) {
    f.add(p.x());
    f.add(p.y());
    f.add(p.z());
  }
  f.add(scene.polygons.size());
  for (const ScenePolygon& poly : scene.polygons) {
    f.add(poly.material);
    f.add(poly.vertices.size());
    for (int v : poly.vertices) f.add(v);
  }
  f.add(scene.materials.size());
  for (const Material& m : scene.materials) {
    f.add(m.name);
    f.add(m.diffuse);
    f.add(m.emission);
    f.add(m.specular);
    f.add(m.transmittance);
    f.add(m.ior);
    f.add(static_cast<int>(m.kind));
  }
  f.add(static_cast<int>(o.solver));
  f.add(o.raysPerElement);
  f.add(o.maxArea);
  f.add(o.targetElements);
  f.add(o.seed);
  f.add(o.tolerance);
  f.add(o.maxIterations);
  f.add(o.bounces);
  f.add(static_cast<int>(o.formFactors));
  f.add(o.patchArea);
  f.add(o.shadowRays);
  f.add(o.receiverPoints);
  return f.hex();
}

bool solutionIsReusable(const SolveOptions& options) {
  return !(options.refineThreshold > 0) && !options.keepBounceTerms;
}

std::optional<SolveResult> loadSavedSolution(const std::string& dir, const Scene& scene,
                                             const SolveOptions& options, std::string& whyNot) {
  const std::filesystem::path base(dir);
  const std::string jsonPath = (base / kSolutionJson).string();
  const std::string csvPath = (base / kSolutionCsv).string();
  if (!solutionIsReusable(options)) {
    whyNot = options.keepBounceTerms ? "--bounces-separate: the Jacobi terms are not saved"
                                     : "adaptive refinement: the mesh depends on the solve";
    return std::nullopt;
  }
  if (!std::filesystem::exists(jsonPath) || !std::filesystem::exists(csvPath)) {
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

  SolveResult result;
  result.mesh = remesh(scene, options);
  const PatchMesh& mesh = *result.mesh;
  const int count = mesh.elementCount();
  result.radiosity.assign(count, Rgb());
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
    result.radiosity[element++] = row.radiosity;
  }
  if (element != count)
    throw InputError(csvPath, lineNumber,
                     "the saved solution has " + std::to_string(element) +
                         " elements, the re-meshed scene " + std::to_string(count));
  result.scene = scene;
  result.solverName = meta.value("solver", std::string("saved")) + " (reused)";
  result.converged = meta.value("converged", false);
  result.maxArea =
      options.maxArea > 0 ? options.maxArea : mesh.totalArea() / options.targetElements;
  return result;
}

void writeSavedSolution(AtomicFile& csv, AtomicFile& json, const SolveResult& result,
                        const SolveOptions& options) {
  writeElementsCsv(csv.stream(), *result.mesh, result.radiosity);
  const nlohmann::json meta = {
      {"format", kFormat},
      {"fingerprint", solutionFingerprint(result.scene, options)},
      {"scene", options.scenePath},
      {"elements", result.mesh->elementCount()},
      {"solver", result.solverName},
      {"converged", result.converged},
      {"rays_per_element", options.raysPerElement},
      {"seed", options.seed},
      {"comment",
       "B per element in solution.csv (W/m^2); radiosity render --out on this directory reuses "
       "it for the same scene and solve options"},
  };
  json.stream() << meta.dump(2) << "\n";
}

}  // namespace rad
