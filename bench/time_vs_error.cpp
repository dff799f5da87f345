// Run time against error (issue 8): solves one scene with many configurations (rays per element,
// element budget uniform and adaptive, form-factor method, solver, tolerance) and measures each
// one's wall time and its error against a converged reference solution of the same scene.
//
// Error: relative RMS of the radiance per element, area-weighted, at the reference's element
// centroids: each centroid takes the radiance of the configuration's element that contains it
// (elements of the same input polygon), so meshes of any resolution compare on the same points.
// Emitters are left out (their emission is exact in every configuration).
//
//   time_vs_error SCENE.obj --name NAME --out DIR [--elements 250,1000,3000] [--rays 64,256,1024]
//                 [--analytic-elements LIST (default: --elements; analytic costs elements ×
//                 patches)]
//                 [--reference analytic|hemisphere] [--reference-elements N] [--reference-rays N]
//                 [--threads T]
//
// Writes DIR/time_vs_error_NAME.csv, one row per configuration (renamed into place once complete);
// bench/plot_time_vs_error.py draws the plots. The reference is, by default, the analytic method
// (patches shoot, elements receive; its cost grows as elements × patches, so large scenes take
// --reference hemisphere: many rays per element instead). Scenes with mirrors or glass need the
// hemisphere rays' specular continuation, so their reference is always hemisphere rows, and
// analytic configurations (and adaptive refinement, which builds on them) are skipped there. The
// reference's own Monte Carlo noise is measured by a second reference run with another seed and
// written with every row.
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "meshing/element_locator.h"
#include "radiosity/core/atomic_file.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"

namespace {

using namespace rad;

struct Config {
  SolveOptions options;
  std::string label;  // what varies, for the log
};

// The radiance (B/π) of a solution at a point of an input polygon: the value of the element of
// that polygon containing the point (ElementLocator: the one it is least outside of when rounding
// puts it just outside all of them).
class ElementLookup {
 public:
  explicit ElementLookup(const SolveResult& r) : result_(r), locator_(*r.solution.mesh) {}

  Eigen::Vector3d radianceAt(int patch, const Eigen::Vector3d& p) const {
    Eigen::Vector3d weights;
    const Rgb& b = result_.solution.radiosity[locator_.locate(patch, p, weights)];
    return Eigen::Vector3d(b.r, b.g, b.b) / M_PI;
  }

 private:
  const SolveResult& result_;
  ElementLocator locator_;
};

double relativeRmsError(const SolveResult& reference, const SolveResult& candidate) {
  const ElementLookup lookup(candidate);
  const PatchMesh& ref = *reference.solution.mesh;
  double num = 0, den = 0;
  for (int e = 0; e < ref.elementCount(); ++e) {
    if (reference.solution.problem.emission[e].maxComponent() > 0) continue;
    const Rgb& b = reference.solution.radiosity[e];
    const Eigen::Vector3d truth = Eigen::Vector3d(b.r, b.g, b.b) / M_PI;
    const Eigen::Vector3d value = lookup.radianceAt(ref.patch(e), ref.centroid(e));
    num += ref.area(e) * (value - truth).squaredNorm();
    den += ref.area(e) * truth.squaredNorm();
  }
  return std::sqrt(num / den);
}

std::vector<int> parseList(const std::string& text) {
  std::vector<int> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const int v = std::stoi(item);
    if (v < 1) throw std::invalid_argument("list values must be positive: " + text);
    out.push_back(v);
  }
  if (out.empty()) throw std::invalid_argument("empty list");
  return out;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

std::string format(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// The sweep: a grid of element budget × rays with progressive shooting, each solver and looser
// tolerances at the middle of the grid, and (diffuse scenes) analytic form factors uniform and
// adaptive.
std::vector<Config> sweep(const std::vector<int>& elements, const std::vector<int>& rays,
                          const std::vector<int>& analyticElements, bool specular, int threads) {
  std::vector<Config> configs;
  auto add = [&](SolveOptions o) {
    o.threads = threads;
    std::string label = (o.formFactors == FormFactorMethod::Analytic
                             ? "analytic"
                             : "hemisphere " + std::to_string(o.raysPerElement) + " rays") +
                        ", " + solverKindName(o.solver) + ", " + std::to_string(o.targetElements) +
                        " elements, tolerance " + format(o.tolerance);
    if (o.refineThreshold > 0) label += ", refine " + format(o.refineThreshold);
    configs.push_back({o, label});
  };
  const int midElements = elements[elements.size() / 2], midRays = rays[rays.size() / 2];
  const int midAnalytic = analyticElements[analyticElements.size() / 2];
  for (int n : elements)
    for (int r : rays) {
      SolveOptions o;
      o.targetElements = n;
      o.raysPerElement = r;
      add(o);
    }
  for (SolverKind s : {SolverKind::Southwell, SolverKind::GaussSeidel, SolverKind::Jacobi}) {
    SolveOptions o;
    o.targetElements = midElements;
    o.raysPerElement = midRays;
    o.solver = s;
    add(o);
  }
  for (double tolerance : {1e-2})
    for (SolverKind s : {SolverKind::Progressive, SolverKind::GaussSeidel}) {
      SolveOptions o;
      o.targetElements = midElements;
      o.raysPerElement = midRays;
      o.solver = s;
      o.tolerance = tolerance;
      add(o);
    }
  if (specular) return configs;
  for (int n : analyticElements) {
    SolveOptions o;
    o.formFactors = FormFactorMethod::Analytic;
    o.targetElements = n;
    add(o);
  }
  {
    SolveOptions o;
    o.formFactors = FormFactorMethod::Analytic;
    o.targetElements = midAnalytic;
    o.solver = SolverKind::GaussSeidel;
    add(o);
  }
  // Adaptive: start coarser than the uniform meshes and let refinement add elements where the
  // radiance jumps or shadows fall (budget: 8 × the start, the solver's default).
  for (double threshold : {0.1})
    for (size_t k = 0; k + 1 < analyticElements.size(); ++k) {
      SolveOptions o;
      o.formFactors = FormFactorMethod::Analytic;
      o.targetElements = analyticElements[k] / 2;
      o.refineThreshold = threshold;
      o.refinePasses = 3;
      add(o);
    }
  return configs;
}

int usage() {
  std::fprintf(
      stderr,
      "usage: time_vs_error SCENE.obj --name NAME --out DIR [--elements a,b,c] [--rays a,b,c]\n"
      "                     [--analytic-elements a,b,c]\n"
      "                     [--reference analytic|hemisphere] [--reference-elements N]\n"
      "                     [--reference-rays N] [--threads T]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string scenePath = argv[1];
  std::string name, outDir;
  std::vector<int> elements = {250, 1000, 3000}, rays = {64, 256, 1024}, analyticElements;
  int referenceElements = 3000, referenceRays = 4096, threads = 0;
  bool analyticReference = true;  // on diffuse scenes
  try {
    for (int i = 2; i < argc; i += 2) {
      const std::string flag = argv[i];
      if (i + 1 >= argc) return usage();
      const std::string value = argv[i + 1];
      if (flag == "--name")
        name = value;
      else if (flag == "--out")
        outDir = value;
      else if (flag == "--elements")
        elements = parseList(value);
      else if (flag == "--rays")
        rays = parseList(value);
      else if (flag == "--analytic-elements")
        analyticElements = parseList(value);
      else if (flag == "--reference-elements")
        referenceElements = parseList(value).at(0);
      else if (flag == "--reference-rays")
        referenceRays = parseList(value).at(0);
      else if (flag == "--reference") {
        if (value != "analytic" && value != "hemisphere")
          throw std::invalid_argument("--reference " + value);
        analyticReference = value == "analytic";
      } else if (flag == "--threads")
        threads = std::stoi(value);
      else {
        std::fprintf(stderr, "time_vs_error: unknown option %s\n", flag.c_str());
        return usage();
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "time_vs_error: bad option value (%s)\n", e.what());
    return 2;
  }
  if (name.empty() || outDir.empty()) return usage();
  if (analyticElements.empty()) analyticElements = elements;
  setLogLevel(LogLevel::Quiet);

  try {
    const Scene scene = loadScene(scenePath);
    const bool specular = scene.hasSpecular();

    // Reference, twice with different seeds: the second measures the reference's own noise.
    SolveOptions ref;
    ref.threads = threads;
    ref.targetElements = referenceElements;
    ref.tolerance = 1e-7;
    ref.seed = 1001;  // not the configurations' seed: a configuration equal to the reference in
                      // every setting still gets independent noise
    const bool analytic = analyticReference && !specular;
    if (analytic)
      ref.formFactors = FormFactorMethod::Analytic;
    else
      ref.raysPerElement = referenceRays;
    auto t0 = std::chrono::steady_clock::now();
    const SolveResult reference = solveScene(scene, ref);
    const double referenceSeconds = seconds(t0);
    ref.seed = 1002;
    const SolveResult referenceAgain = solveScene(scene, ref);
    // Two independent estimates differ by sqrt(2) times the noise of one.
    const double referenceNoise = relativeRmsError(reference, referenceAgain) / std::sqrt(2.0);
    std::fprintf(
        stderr, "%s: reference %s, %d elements, %.1f s, own noise %.4f (relative RMS)\n",
        name.c_str(),
        analytic ? "analytic" : ("hemisphere " + std::to_string(referenceRays) + " rays").c_str(),
        reference.solution.mesh->elementCount(), referenceSeconds, referenceNoise);
    if (specular)
      std::fprintf(
          stderr,
          "%s: analytic form factors and adaptive refinement skipped: the scene has mirrors or "
          "glass, which only hemisphere rows carry light through\n",
          name.c_str());

    AtomicFile file(outDir + "/time_vs_error_" + name + ".csv");
    std::ostream& csv = file.stream();
    csv << "scene,form_factors,solver,rays,target_elements,refine_threshold,tolerance,elements,"
           "seconds,"
           "relative_rmse,converged,reference_elements,reference_noise\n";
    for (const Config& c : sweep(elements, rays, analyticElements, specular, threads)) {
      t0 = std::chrono::steady_clock::now();
      const SolveResult r = solveScene(scene, c.options);
      const double wall = seconds(t0);
      const double error = relativeRmsError(reference, r);
      const SolveOptions& o = c.options;
      const bool analyticConfig = o.formFactors == FormFactorMethod::Analytic;
      csv << name << ',' << (analyticConfig ? "analytic" : "hemisphere") << ','
          << solverKindName(o.solver) << ',' << (analyticConfig ? 0 : o.raysPerElement) << ','
          << o.targetElements << ',' << o.refineThreshold << ',' << o.tolerance << ','
          << r.solution.mesh->elementCount() << ',' << wall << ',' << error << ','
          << (r.report.converged ? 1 : 0) << ',' << reference.solution.mesh->elementCount() << ','
          << referenceNoise << '\n';
      std::fprintf(stderr, "%s: %-70s %6d elements %7.2f s  error %.4f\n", name.c_str(),
                   c.label.c_str(), r.solution.mesh->elementCount(), wall, error);
    }
    file.commit();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "time_vs_error: %s\n", e.what());
    return 1;
  }
  return 0;
}
