#include "radiosity/app/solve_job.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "meshing/adaptive_refinement.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/progress.h"
#include "radiosity/formfactors/analytic_patch_shots.h"
#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

// Limits checked before the work starts, so absurd options fail at once with a clear message.
constexpr int kMaxRaysPerElement = 1 << 24;  // × 64 for emitter rows still fits an int
constexpr double kMaxElements = 4e6;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

void note(SolveResult& result, std::string what, std::string why) {
  logInfo("skipped: " + what + " (" + why + ")");
  result.skipped.push_back({std::move(what), std::move(why)});
}

}  // namespace

int defaultMaxIterations(SolverKind kind, int elements) {
  switch (kind) {
    case SolverKind::Progressive:
    case SolverKind::Southwell:
      return std::max(100000, 200 * elements);
    case SolverKind::GaussSeidel:
      return 10000;
    case SolverKind::Jacobi:
      return 10000;
  }
  return 10000;
}

// A shooter's row decides how evenly its power lands on the receivers. An emitter element shoots a
// large share of all the light (all of it, at first), so its row gets rays in proportion to that
// share: with n elements, an element emitting the fraction s of the power gets about s·n times
// the rays of an average element (at least 1×, at most 64×). A uniform emitter gets 1×.
std::vector<int> emitterRayMultipliers(const RadiosityProblem& problem) {
  const double emitted = problem.emittedPower();
  std::vector<int> multiplier(problem.size(), 1);
  if (!(emitted > 0)) return multiplier;
  for (int i = 0; i < problem.size(); ++i) {
    const double share = problem.area[i] * problem.emission[i].sum() / emitted;
    multiplier[i] = static_cast<int>(std::clamp(std::round(share * problem.size()), 1.0, 64.0));
  }
  return multiplier;
}

FormFactorMethod parseFormFactorMethod(const std::string& name) {
  if (name == "hemisphere") return FormFactorMethod::Hemisphere;
  if (name == "analytic") return FormFactorMethod::Analytic;
  throw InputError("unknown form-factor method '" + name + "' (expected hemisphere or analytic)");
}

SolverKind parseSolverKind(const std::string& name) {
  if (name == "progressive") return SolverKind::Progressive;
  if (name == "southwell") return SolverKind::Southwell;
  if (name == "gauss-seidel") return SolverKind::GaussSeidel;
  if (name == "jacobi") return SolverKind::Jacobi;
  throw InputError("unknown solver '" + name +
                   "' (expected progressive, southwell, gauss-seidel or jacobi)");
}

std::string solverKindName(SolverKind kind) {
  switch (kind) {
    case SolverKind::Progressive:
      return "progressive";
    case SolverKind::Southwell:
      return "southwell";
    case SolverKind::GaussSeidel:
      return "gauss-seidel";
    case SolverKind::Jacobi:
      return "jacobi";
  }
  return "?";
}

std::vector<SpecularSurface> specularSurfaces(const Scene& scene, const PatchMesh& mesh) {
  std::vector<SpecularSurface> surfaces(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Material& m = scene.materials[mesh.material(e)];
    if (m.kind == SurfaceKind::Mirror)
      surfaces[e] = {SpecularSurface::Kind::Mirror, m.specular, Rgb::all(1), 1};
    if (m.kind == SurfaceKind::Dielectric)
      surfaces[e] = {SpecularSurface::Kind::Dielectric, Rgb::all(1), m.transmittance, m.ior};
  }
  return surfaces;
}

RadiosityProblem makeProblem(const Scene& scene, const PatchMesh& mesh) {
  RadiosityProblem problem;
  const int n = mesh.elementCount();
  problem.emission.resize(n);
  problem.reflectance.resize(n);
  problem.area.resize(n);
  for (int e = 0; e < n; ++e) {
    const Material& m = scene.materials[mesh.material(e)];
    problem.emission[e] = M_PI * m.emission;  // Lambertian emitter: exitance = pi × radiance
    // Mirrors and glass hold no radiosity: rays pass on through them (extended form factors).
    problem.reflectance[e] = m.isSpecular() ? Rgb() : m.diffuse;
    problem.area[e] = mesh.area(e);
  }
  return problem;
}

uint64_t formFactorMemoryEstimate(FormFactorMethod method, int elements, int shooters, int rays,
                                  int receiverPoints) {
  constexpr uint64_t kBytesPerEntry = 12;   // 4-byte column index + 8-byte value
  constexpr uint64_t kBytesPerPoints = 12;  // 3 single-precision point factors
  const uint64_t n = static_cast<uint64_t>(std::max(elements, 0));
  if (method == FormFactorMethod::Analytic)
    return n * static_cast<uint64_t>(std::max(shooters, 0)) *
           (kBytesPerEntry + (receiverPoints == 3 ? kBytesPerPoints : 0));
  return n * std::min<uint64_t>(static_cast<uint64_t>(std::max(rays, 0)), n) * kBytesPerEntry;
}

uint64_t availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  uint64_t value = 0;
  while (in >> key >> value >> unit)
    if (key == "MemAvailable:") return value * 1024;  // reported in kB
  return 0;
}

void checkFormFactorMemory(uint64_t needed, uint64_t available, FormFactorMethod method) {
  if (available == 0 || needed <= available) return;
  const auto gib = [](uint64_t bytes) { return formatNumber(bytes / double(1ull << 30)) + " GiB"; };
  throw InputError(
      "the form-factor rows may need up to " + gib(needed) + " but only " + gib(available) +
      " of memory is available: " +
      (method == FormFactorMethod::Analytic
           ? "raise --patch-area (fewer shooting patches) or --max-area (fewer elements), "
             "or lower --elements"
           : "lower --elements or raise --max-area (fewer elements), or lower --rays"));
}

void checkSceneLimits(const Scene& scene) {
  if (scene.polygons.size() > kMaxElements)
    throw InputError(scene.sourcePath, 0,
                     std::to_string(scene.polygons.size()) +
                         " polygons, more than the element limit " + formatNumber(kMaxElements) +
                         ": every polygon needs at least one element");
  // Beyond this, double precision leaves less than a millimetre-per-kilometre of resolution and
  // Embree's single-precision BVH cannot separate nearby surfaces.
  for (std::size_t i = 0; i < scene.positions.size(); ++i)
    if (!scene.positions[i].allFinite() ||
        !(scene.positions[i].cwiseAbs().maxCoeff() <= kMaxCoordinate))
      throw InputError(scene.sourcePath, 0,
                       "vertex " + std::to_string(i + 1) + " has a coordinate beyond " +
                           formatNumber(kMaxCoordinate) + " scene units: rescale the scene");
}

namespace {

// Each polygon is one patch, in scene order. One whose triangles hold no area (or a NaN one)
// would be dropped silently by everything after; it is named by its `f` line instead.
void checkPatchAreas(const PatchMesh& mesh, const Scene& scene) {
  if (mesh.patchCount() != static_cast<int>(scene.polygons.size())) return;
  std::vector<double> areas(scene.polygons.size(), 0.0);
  for (int e = 0; e < mesh.elementCount(); ++e) areas[mesh.patch(e)] += mesh.area(e);
  for (std::size_t p = 0; p < areas.size(); ++p)
    if (!(areas[p] > 0) || !std::isfinite(areas[p]))
      throw InputError(scene.sourcePath, scene.polygons[p].sourceLine,
                       "this face triangulates to " +
                           std::string(std::isfinite(areas[p]) ? "no area" : "a non-finite area") +
                           " (a self-intersecting or degenerate polygon?)");
}

}  // namespace

SolveResult runSolve(const SolveOptions& options) {
  const auto start = Clock::now();
  Scene scene = loadScene(options.scenePath);
  const double loadSeconds = since(start);
  SolveResult result = solveScene(std::move(scene), options);
  result.times.load = loadSeconds;
  result.times.total += loadSeconds;
  return result;
}

SolveResult solveScene(Scene scene, const SolveOptions& options) {
  if (options.raysPerElement < 1) throw InputError("--rays must be at least 1");
  if (options.raysPerElement > kMaxRaysPerElement)
    throw InputError("--rays must be at most " + std::to_string(kMaxRaysPerElement));
  if (options.maxArea < 0 || !std::isfinite(options.maxArea))
    throw InputError("--max-area must be a positive number");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance))
    throw InputError("--tolerance must be a non-negative number");
  if (options.maxIterations < 0) throw InputError("--max-iterations must be non-negative");
  if (options.threads < 0) throw InputError("--threads must be non-negative");
  if (options.shadowRays < 1 || options.shadowRays > 4096)
    throw InputError("--shadow-rays must be between 1 and 4096");
  if (options.receiverPoints != 1 && options.receiverPoints != 3)
    throw InputError("--receiver-points must be 1 or 3");
  if (options.patchArea < 0 || !std::isfinite(options.patchArea))
    throw InputError("--patch-area must be a positive number");
  if (options.refineThreshold < 0 || options.minArea < 0 || options.maxElements < 0 ||
      options.refinePasses < 0)
    throw InputError(
        "--refine-threshold, --min-area, --max-elements and --refine-passes must be non-negative");
  if (options.refineThreshold > 0 && (options.formFactors != FormFactorMethod::Analytic ||
                                      options.solver != SolverKind::Progressive))
    throw InputError(
        "adaptive refinement (--refine-threshold) needs --form-factors analytic and "
        "--solver progressive: patches keep shooting while the elements are refined");
  if (!(options.timeLimit >= 0) || !std::isfinite(options.timeLimit))
    throw InputError("--time-limit must be a non-negative number of seconds");
  if (options.bounces >= 0 && options.solver != SolverKind::Jacobi)
    throw InputError("--bounces applies to --solver jacobi only");

  const auto start = Clock::now();
  SolveResult result;
  result.threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(result.threads));

  result.scene = std::move(scene);
  checkSceneLimits(result.scene);  // first: a face lost to overflow would read as "no emitter"
  requireEmitter(result.scene);
  const bool specular = result.scene.hasSpecular();
  if (!specular)
    note(result, "specular continuation", "the scene has no mirror or glass material");
  else if (options.formFactors == FormFactorMethod::Analytic)
    logWarning(
        "analytic form factors do not follow mirrors and glass: they absorb light in this "
        "pass; use --form-factors hemisphere for light carried through them");

  auto t = Clock::now();
  result.mesh = std::make_unique<PatchMesh>(buildPatchMesh(result.scene));
  checkPatchAreas(*result.mesh, result.scene);
  const double totalArea = result.mesh->totalArea();
  if (!(totalArea > 0) || !std::isfinite(totalArea))
    throw InputError(
        result.scene.sourcePath, 0,
        "the polygons triangulate to no area (self-intersecting or degenerate faces?)");
  result.maxArea = options.maxArea > 0 ? options.maxArea : totalArea / options.targetElements;
  // Decided before any work: bisection gives at most about 2·totalArea/maxArea elements.
  if (totalArea / result.maxArea > kMaxElements)
    throw InputError("about " + formatNumber(totalArea / result.maxArea) +
                     " elements requested (limit " + formatNumber(kMaxElements) +
                     "): raise --max-area or lower --elements");
  {
    // Also decided before any work: the worst case of the form-factor rows must fit in memory.
    const double elements = std::ceil(totalArea / result.maxArea);
    const double patches = options.formFactors == FormFactorMethod::Analytic
                               ? std::ceil(totalArea / (options.patchArea > 0 ? options.patchArea
                                                                              : 8 * result.maxArea))
                               : elements;
    checkFormFactorMemory(formFactorMemoryEstimate(options.formFactors, static_cast<int>(elements),
                                                   static_cast<int>(std::min(patches, elements)),
                                                   options.raysPerElement, options.receiverPoints),
                          availableMemoryBytes(), options.formFactors);
  }
  if (options.formFactors == FormFactorMethod::Analytic) {
    // Shooting patches first (coarser), then elements inside them.
    const double patchArea = options.patchArea > 0 ? options.patchArea : 8 * result.maxArea;
    if (patchArea < result.maxArea)
      throw InputError("--patch-area must not be below the element area");
    result.mesh->subdivideUniform(patchArea);
    result.mesh->markShooters();
  }
  result.mesh->subdivideUniform(result.maxArea);
  const PatchMesh& mesh = *result.mesh;
  result.times.mesh = since(t);
  logInfo("mesh: " + std::to_string(mesh.patchCount()) + " patches, " +
          std::to_string(mesh.elementCount()) + " elements (max area " +
          formatNumber(result.maxArea) + ")");

  throwIfInterrupted();
  t = Clock::now();
  RayCaster rays(mesh);
  result.times.bvh = since(t);

  result.problem = makeProblem(result.scene, mesh);
  const RadiosityProblem& problem = result.problem;

  int blackElements = 0;
  for (int e = 0; e < mesh.elementCount(); ++e)
    blackElements += problem.reflectance[e].maxComponent() == 0 &&
                     !result.scene.materials[mesh.material(e)].isSpecular();
  if (blackElements > 0)
    note(result, "re-shooting from " + std::to_string(blackElements) + " black elements",
         "reflectance 0: they receive light but pass none on");

  // Form factors: hemisphere rows per element, or analytic element-to-patch factors with
  // patches (coarser shooters) marked on the mesh before it is refined to elements.
  HemisphereFormFactors method(
      mesh, rays,
      {options.raysPerElement, options.seed, emitterRayMultipliers(problem),
       specular ? specularSurfaces(result.scene, mesh) : std::vector<SpecularSurface>()});
  FormFactorCache cache(method);
  std::unique_ptr<AnalyticPatchShots> analytic;
  if (options.formFactors == FormFactorMethod::Analytic)
    analytic = std::make_unique<AnalyticPatchShots>(
        mesh, rays, AnalyticOptions{options.receiverPoints, options.shadowRays, options.seed});
  if (analytic) {
    // Shadow boundaries worth refining are those of the emitters' direct light.
    std::vector<char> emitting(mesh.shooterCount(), 0);
    for (int e = 0; e < mesh.elementCount(); ++e)
      if (problem.emission[e].maxComponent() > 0) emitting[mesh.shooter(e)] = 1;
    analytic->setShadowCasters(std::move(emitting));
  }
  ShotRows& shots = analytic ? static_cast<ShotRows&>(*analytic) : cache;
  result.formFactorMethod = analytic ? "analytic" : "hemisphere";
  result.shooters = shots.shooterCount();
  throwIfInterrupted();

  t = Clock::now();
  std::unique_ptr<Solver> solver;
  std::unique_ptr<GatheringColumns> columns;
  double tolerance = options.tolerance;
  int maxIterations = options.maxIterations > 0
                          ? options.maxIterations
                          : defaultMaxIterations(options.solver, mesh.elementCount());
  if (options.solver == SolverKind::Progressive) {
    solver = std::make_unique<ProgressiveSolver>(problem, shots);
  } else {
    SparseRows f;
    if (analytic) {
      Progress progress("form factors", shots.shooterCount(), "patches");
      f = analytic->gatheringMatrix(&progress);
      progress.finish();
    } else {
      uint64_t totalRays = 0;
      for (int e = 0; e < mesh.elementCount(); ++e) totalRays += method.raysForRow(e);
      Progress progress("form factors", totalRays, "rays");
      f = gatherMatrix(problem, cache, &progress);
      progress.finish(std::to_string(cache.rowsComputed()) + " rows");
    }
    if (options.solver == SolverKind::Southwell) {
      columns = std::make_unique<GatheringColumns>(problem, f);
      solver = std::make_unique<ProgressiveSolver>(problem, *columns);
      static_cast<ProgressiveSolver&>(*solver).setName("southwell");
    } else if (options.solver == SolverKind::Jacobi) {
      solver = std::make_unique<JacobiSolver>(problem, std::move(f));
      if (options.bounces >= 0) {
        maxIterations = options.bounces;
        tolerance = 0;  // exactly that many bounces
      }
    } else {
      solver = std::make_unique<GaussSeidelSolver>(problem, std::move(f));
    }
  }

  const bool refine = options.refineThreshold > 0;
  // The budget, and the smallest element: 1/16 of the area elements would have if the whole
  // budget were spread evenly, so shadow edges can be resolved well below the even spacing.
  const int budget = options.maxElements > 0 ? options.maxElements : 8 * mesh.elementCount();
  RefinementOptions refinement{options.refineThreshold,
                               options.minArea > 0 ? options.minArea : totalArea / budget / 16,
                               budget};
  result.elementsBeforeRefinement = mesh.elementCount();
  int unrefined = -1;  // elements the last refinement pass left alone
  for (int pass = 0;; ++pass) {
    Progress progress("solve (" + solver->name() + ")", 0, "iterations");
    const double startMeasure = std::max(solver->progress(), 1e-300);
    bool outOfTime = false;
    const bool keepTerms = options.keepBounceTerms && options.solver == SolverKind::Jacobi;
    std::vector<Rgb> previous;
    if (keepTerms) result.bounceTerms.push_back(previous = solver->solution());  // B_0 = E
    while (solver->iterations() < maxIterations && solver->progress() > tolerance) {
      throwIfInterrupted();
      if (options.timeLimit > 0 && since(start) >= options.timeLimit) {
        outOfTime = true;  // keep the solution reached so far, flagged as not converged
        break;
      }
      solver->step();
      progress.advance();
      if (keepTerms) {
        std::vector<Rgb> term = solver->solution();
        for (size_t e = 0; e < term.size(); ++e) term[e] -= previous[e];
        previous = solver->solution();
        result.bounceTerms.push_back(std::move(term));
      }
      if (tolerance > 0 && solver->progress() > 0) {
        // Fraction of the way, on a log scale, from the starting measure to the tolerance.
        const double f =
            std::log(startMeasure / solver->progress()) / std::log(startMeasure / tolerance);
        progress.setFraction(std::clamp(f, 0.0, 1.0),
                             solver->progressMeasure() + " " + formatNumber(solver->progress()));
      }
    }
    result.converged = !outOfTime && (options.bounces >= 0 ? solver->iterations() == options.bounces
                                                           : solver->progress() <= tolerance);
    result.stoppedBy = outOfTime          ? "time limit"
                       : result.converged ? (options.bounces >= 0 ? "bounces" : "tolerance")
                                          : "iteration limit";
    progress.finish(solver->progressMeasure() + " " + formatNumber(solver->progress()) +
                    (result.converged ? "" : " (not converged)"));
    if (!refine || pass == options.refinePasses || !result.converged) break;
    // Adaptive refinement: split where the displayed radiance departs most from the solution or a
    // shadow boundary crosses, up to this pass's share of the element budget, then let the new
    // elements gather what was already shot and carry on shooting.
    std::vector<int> selected;
    if (options.receiverPoints == 3) {
      // The receiver points resolve a linear field per element: refine by what is displayed
      // against them.
      const auto& atPoints = static_cast<ProgressiveSolver&>(*solver).pointSolution();
      std::vector<std::array<double, 3>> luminance(mesh.elementCount());
      for (int e = 0; e < mesh.elementCount(); ++e)
        for (int k = 0; k < 3; ++k) luminance[e][k] = atPoints[e][k].luminance();
      selected = selectForRefinement(mesh, luminance, analytic->partlyShadowed(), refinement);
    } else {
      std::vector<double> luminance(mesh.elementCount());
      for (int e = 0; e < mesh.elementCount(); ++e)
        luminance[e] = solver->solution()[e].luminance();
      selected = selectForRefinement(mesh, luminance, analytic->partlyShadowed(), refinement);
    }
    unrefined = mesh.elementCount() - static_cast<int>(selected.size());
    if (selected.empty()) break;
    const int before = mesh.elementCount();
    const int target = refinementTarget(result.elementsBeforeRefinement, refinement.maxElements,
                                        pass, std::max(1, options.refinePasses));
    const std::vector<int> changed = refineElements(*result.mesh, selected, refinement, target);
    result.problem = makeProblem(result.scene, mesh);
    analytic->meshChanged(changed);
    static_cast<ProgressiveSolver&>(*solver).elementsChanged(
        changed, [&](int e, int s) { return analytic->elementToShooterAtPointsCached(e, s); });
    ++result.refinementPasses;
    logInfo("refinement pass " + std::to_string(pass + 1) + ": " + std::to_string(selected.size()) +
            " candidates, " + std::to_string(before) + " → " + std::to_string(mesh.elementCount()) +
            " elements");
    if (mesh.elementCount() >= refinement.maxElements) {
      note(result, "further refinement", "the element budget (--max-elements) is reached");
      break;
    }
  }
  if (unrefined > 0)
    note(result, "splitting " + std::to_string(unrefined) + " elements in the last refinement pass",
         "the radiance displayed over them is within the threshold of their solved value and no "
         "emitter shadow crosses them");
  const double solveAndRows = since(t);
  result.times.formFactors = analytic ? analytic->seconds() : cache.seconds();
  result.times.solve = std::max(0.0, solveAndRows - result.times.formFactors);

  result.radiosity = solver->solution();
  const auto* shooting = dynamic_cast<const ProgressiveSolver*>(solver.get());
  if (shooting && analytic && options.receiverPoints == 3)
    result.pointRadiosity = shooting->pointSolution();
  const std::vector<Rgb> unshot = shooting ? shooting->unshotPowerOfElements() : std::vector<Rgb>();
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Rgb& b = result.radiosity[e];
    result.mesh->setRadiosity(e, {b.r, b.g, b.b});
    if (shooting) result.mesh->setUnshot(e, {unshot[e].r, unshot[e].g, unshot[e].b});
  }
  result.solverName = solver->name();
  result.progressMeasure = solver->progressMeasure();
  result.iterations = solver->iterations();
  result.finalProgress = solver->progress();
  result.rowsComputed = analytic ? analytic->rowsComputed() : cache.rowsComputed();
  result.raysCast = analytic ? analytic->raysCast() : cache.raysCast() + method.specularRays();
  result.specularRays = analytic ? 0 : method.specularRays();
  if (result.rowsComputed < result.shooters) {
    // Hemisphere rows have a known ray count each: report what skipping them saved.
    uint64_t raysSaved = 0;
    if (!analytic)
      for (int e = 0; e < mesh.elementCount(); ++e)
        if (!cache.hasRow(e)) raysSaved += method.raysForRow(e);
    note(result,
         "form-factor rows of " + std::to_string(result.shooters - result.rowsComputed) +
             (analytic ? " patches" : " elements") +
             (analytic ? std::string() : " (" + std::to_string(raysSaved) + " rays saved)"),
         options.solver == SolverKind::Progressive ? "they never held unshot power worth shooting"
                                                   : "black elements pass no light on");
  }
  if (analytic)
    note(result, "shadow rays between element–patch pairs facing away from each other or coplanar",
         "they cannot exchange light; the pairs are not counted");
  if (result.stoppedBy == "time limit")
    logWarning("time limit of " + formatNumber(options.timeLimit) + " s reached after " +
               std::to_string(result.iterations) + " iterations: writing the solution so far (" +
               solver->progressMeasure() + " " + formatNumber(result.finalProgress) +
               ", not converged)");
  else if (!result.converged && options.bounces < 0)
    logWarning("stopped after " + std::to_string(result.iterations) + " iterations with " +
               solver->progressMeasure() + " " + formatNumber(result.finalProgress) +
               " above the tolerance " + formatNumber(tolerance));
  result.times.total = since(start);
  return result;
}

}  // namespace rad
