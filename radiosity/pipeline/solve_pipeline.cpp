#include "radiosity/pipeline/solve_pipeline.h"

#include <chrono>
#include <memory>
#include <string>

#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/hierarchical_solve.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/light_group_solve.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/pipeline/row_solve.h"
#include "radiosity/pipeline/solve_stages.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

// The scene's own limits and what it lets the run skip, before any meshing.
void checkScene(const Scene& scene, const SolveOptions& options, SolveReport& report) {
  checkSceneLimits(scene);  // first: a face lost to overflow would read as "no emitter"
  requireEmitter(scene);
  if (!scene.hasSpecular())
    report.skip("specular continuation", "the scene has no mirror or glass material");
  else if (options.formFactors == FormFactorMethod::Analytic)
    logWarning(
        "analytic form factors do not follow mirrors and glass: they absorb light in this "
        "pass; use --form-factors hemisphere for light carried through them");
}

void noteBuriedParts(const ElementExposure& exposure, const PatchMesh& mesh, SolveReport& report) {
  report.partlyBuried = exposure.partlyBuried();
  report.fullyBuried = exposure.fullyBuried();
  report.buriedAreaFraction = exposure.buriedArea() / mesh.totalArea();
  report.exposureProbeRays = exposure.probeRays();
  if (exposure.fullyBuried() > 0)
    report.skip("shooting from " + std::to_string(exposure.fullyBuried()) + " buried elements",
                "enclosed by one-sided geometry: no light reaches them");
  if (exposure.partlyBuried() + exposure.fullyBuried() > 0)
    logInfo("buried: " + std::to_string(exposure.partlyBuried()) + " elements partly, " +
            std::to_string(exposure.fullyBuried()) + " fully (" +
            formatNumber(100 * report.buriedAreaFraction) + "% of the area), " +
            std::to_string(exposure.probeRays()) + " probe rays");
}

void warnIfNotConverged(const IterationLimits& limits, const Solution& solution,
                        const SolveReport& report) {
  const std::string reached = report.progressMeasure + " " + formatNumber(report.finalProgress);
  bool reflectsAll = false;
  for (const Rgb& rho : solution.problem.reflectance) reflectsAll |= rho.maxComponent() >= 1;
  const std::string why = reflectsAll ? " (some surfaces have reflectance 1: they keep all the "
                                        "light they receive, so a closed scene never loses it)"
                                      : "";
  if (report.stoppedBy == StopReason::TimeLimit)
    logWarning("time limit of " + formatNumber(limits.timeLimit) + " s reached after " +
               std::to_string(report.iterations) + " iterations: writing the solution so far (" +
               reached + ", not converged)" + why);
  else if (report.stoppedBy == StopReason::IterationLimit && limits.bounces < 0)
    logWarning("stopped after " + std::to_string(report.iterations) + " iterations with " +
               reached + " above the tolerance " + formatNumber(limits.tolerance) + why);
}

// How the radiosity system is solved, chosen once from the options (validateSolveOptions keeps
// the three apart): over element rows, over a hierarchy's links, or once per light group.
enum class SolveStrategy { Rows, Hierarchical, LightGroups };

SolveStrategy solveStrategy(const SolveOptions& options) {
  if (options.lightGroups) return SolveStrategy::LightGroups;
  if (options.solver == SolverKind::Hierarchical) return SolveStrategy::Hierarchical;
  return SolveStrategy::Rows;
}

}  // namespace

SolveResult runSolve(const SolveOptions& options) {
  const auto start = Clock::now();
  Scene scene =
      loadScene(options.scenePath, options.lights, options.twoSided, options.unreadableTextures);
  const double loadSeconds = secondsSince(start);
  SolveResult result = solveScene(std::move(scene), options);
  result.report.times.load = loadSeconds;
  result.report.times.total += loadSeconds;
  return result;
}

SolveResult solveScene(Scene scene, const SolveOptions& options) {
  validateSolveOptions(options);
  const auto start = Clock::now();
  SolveResult result;
  Solution& solution = result.solution;
  SolveReport& report = result.report;
  const ThreadLimit threads = limitSolveThreads(options, report);
  checkScene(scene, options, report);
  solution.scene = std::move(scene);
  const ElementSizing sizing = meshStage(solution, options, report);
  throwIfInterrupted();

  auto t = Clock::now();
  const RayCaster rays(*solution.mesh, solution.scene);
  report.times.bvh = secondsSince(t);
  auto exposure =
      std::make_shared<const ElementExposure>(solveExposure(options, *solution.mesh, rays));
  noteBuriedParts(*exposure, *solution.mesh, report);
  solution.problem = makeProblem(solution.scene, *solution.mesh, exposure.get());
  // For the bake's buried texels, unless refinement changes the mesh.
  if (!(options.refineThreshold > 0)) solution.exposure = exposure;

  const SolveSetup setup{options, rays, *exposure,
                         iterationLimits(options, solution.mesh->elementCount(), start),
                         sizing.edge};
  switch (solveStrategy(options)) {
    case SolveStrategy::Rows:
      result.kept = solveByRows(setup, solution, report);
      break;
    case SolveStrategy::Hierarchical:
      solveByLinks(setup, solution, report);
      break;
    case SolveStrategy::LightGroups:
      solveByLightGroups(setup, solution, report);
      break;
  }
  warnIfNotConverged(setup.limits, solution, report);
  report.times.total = secondsSince(start);
  return result;
}

}  // namespace rad
