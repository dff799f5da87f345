#include "radiosity/pipeline/solve_pipeline.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/emitter_first_shot.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/hierarchical_solve.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/light_group_solve.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/refinement_stage.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/solvers/solver_factory.h"
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

void noteBlackElements(const Solution& solution, SolveReport& report) {
  int black = 0;
  for (int e = 0; e < solution.mesh->elementCount(); ++e)
    black += solution.problem.reflectance[e].maxComponent() == 0 &&
             !solution.scene.materials[solution.mesh->material(e)].isSpecular();
  if (black > 0)
    report.skip("re-shooting from " + std::to_string(black) + " black elements",
                "reflectance 0: they receive light but pass none on");
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

// What the solver reached: B per element, at the receiver points where they resolve it, and the
// unshot power a shooting solver still holds.
void keepSolution(const Solver& solver, bool pointValues, Solution& solution, SolveReport& report) {
  solution.radiosity = solver.solution();
  const auto* shooting = dynamic_cast<const ProgressiveSolver*>(&solver);
  if (shooting && pointValues) solution.pointRadiosity = shooting->pointSolution();
  if (shooting) solution.unshot = shooting->unshotPowerOfElements();
  reportSolver(solver, report);
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

}  // namespace

SolveResult runSolve(const SolveOptions& options) {
  const auto start = Clock::now();
  Scene scene = loadScene(options.scenePath, options.lights, options.twoSided);
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
  report.threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  const tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                        static_cast<size_t>(report.threads));
  checkScene(scene, options, report);
  solution.scene = std::move(scene);

  auto t = Clock::now();
  MeshedScene meshed = meshScene(solution.scene, options);
  solution.mesh = std::move(meshed.mesh);
  report.maxArea = meshed.maxArea;
  report.elementSize = meshed.sizing.edge;
  report.elementSizeRule = elementSizeRuleName(meshed.sizing.rule);
  report.times.mesh = secondsSince(t);
  logInfo("mesh: " + std::to_string(solution.mesh->patchCount()) + " patches, " +
          std::to_string(solution.mesh->elementCount()) + " elements (element size " +
          formatNumber(report.elementSize) + ", set by " +
          (meshed.sizing.rule == ElementSizeRule::SceneDefault
               ? std::string("the scene's extent and area")
               : "--" + report.elementSizeRule) +
          ", max area " + formatNumber(report.maxArea) + ")");
  throwIfInterrupted();
  t = Clock::now();
  const RayCaster rays(*solution.mesh, solution.scene);
  report.times.bvh = secondsSince(t);
  auto keptExposure =
      std::make_shared<const ElementExposure>(solveExposure(options, *solution.mesh, rays));
  const ElementExposure& exposure = *keptExposure;
  noteBuriedParts(exposure, *solution.mesh, report);
  solution.problem = makeProblem(solution.scene, *solution.mesh, &exposure);
  // For the bake's buried texels, unless refinement changes the mesh.
  if (!(options.refineThreshold > 0)) solution.exposure = keptExposure;
  report.elementsBeforeRefinement = solution.mesh->elementCount();
  const IterationLimits limits = iterationLimits(options, solution.mesh->elementCount(), start);
  if (options.lightGroups) {
    // One problem per light group over the same form factors; the whole is their sum.
    std::vector<LightGroupProblem> groups = makeLightGroupProblems(
        solution.scene, *solution.mesh, rays, options, &exposure, solution.problem);
    noteBlackElements(solution, report);
    FormFactorStage formFactors(solution.scene, *solution.mesh, rays, solution.problem, options,
                                &exposure, lightGroupRayMultipliers(groups, solution.problem.area));
    throwIfInterrupted();
    t = Clock::now();
    solveLightGroups(groups, formFactors, options, limits, solution, report);
    const double solveAndRows = secondsSince(t);
    formFactors.report(report, options.solver);
    report.times.solve = std::max(0.0, solveAndRows - report.times.formFactors);
  } else {
    DirectLightStage directLight(solution.scene, *solution.mesh, rays, options, &exposure);
    // Half as many shadow rays per element as the links' rays per receiver: with the emitters'
    // factors in closed form only visibility is sampled, and on the generated room of
    // bench/hierarchical_scale.py at 10^4 elements and --rays 1024, 512 shadow rays per element
    // gave the same error against the path-traced reference as 1024 (1.88% and 1.87%), 256 more
    // (2.26% at --rays 512 against 2.23% with 1024).
    EmitterFirstShot emitterShot(*solution.mesh, rays, exposure, options.seed,
                                 std::max(1, options.raysPerElement / 2));
    double emitterSeconds = 0;
    std::shared_ptr<KeptFactors> kept;
    std::vector<int> rayMultipliers;  // empty: from the problem's emission
    if (options.keepFactors) {
      kept = keepLightsApart(solution, rays, options, exposure, meshed.sizing.edge, rayMultipliers,
                             report);
    } else {
      if (options.solver == SolverKind::Hierarchical) {
        // Its links would gather a small lamp's light by chance: the emitters' direct light by
        // shadow rays instead, and the links carry the reflected light (emitter_first_shot.h).
        t = Clock::now();
        emitterShot.apply(solution.problem);
        emitterSeconds = secondsSince(t);  // form-factor time, added after the solve's is known
        report.raysCast += emitterShot.raysCast();
        if (emitterShot.active())
          logInfo("emitters' direct light: " + std::to_string(emitterShot.emitters()) +
                  " emitting elements, " + std::to_string(emitterShot.raysCast()) +
                  " shadow rays, " + formatNumber(emitterSeconds) + " s");
      }
      directLight.apply(solution.problem);  // the lights' first shot: ρ E_d joins the emission
    }
    noteBlackElements(solution, report);
    if (options.solver == SolverKind::Hierarchical) {
      t = Clock::now();
      solveHierarchical(options, rays, exposure, limits, solution, report);
      emitterShot.restore(solution.problem, solution.radiosity);
      directLight.report(report);
      report.times.solve = std::max(0.0, secondsSince(t) - report.times.formFactors);
      report.times.formFactors += emitterSeconds;
      warnIfNotConverged(limits, solution, report);
      report.times.total = secondsSince(start);
      return result;
    }
    FormFactorStage formFactors(solution.scene, *solution.mesh, rays, solution.problem, options,
                                &exposure, std::move(rayMultipliers));
    throwIfInterrupted();

    t = Clock::now();
    const std::unique_ptr<Solver> solver =
        makeSolver(options.solver, solution.problem, formFactors.shots(),
                   [&] { return formFactors.gatheringMatrix(); });
    const bool keepTerms = options.keepBounceTerms && options.solver == SolverKind::Jacobi;
    AdaptiveRefinement refinement(options, *solution.mesh);
    for (int pass = 0;; ++pass) {
      report.stoppedBy = iterate(*solver, limits, keepTerms ? &solution.bounceTerms : nullptr);
      report.converged = converged(report.stoppedBy);
      if (!report.converged ||
          !refinement.refine(pass, solution, formFactors, directLight, *solver, report))
        break;
    }
    refinement.finish(report);
    const double solveAndRows = secondsSince(t);
    if (kept)
      kept->rows =
          KeptRowTable(formFactors.takeAllRows());  // the rows shooting never asked for too
    formFactors.report(report, options.solver);
    if (!kept) directLight.report(report);
    report.times.solve = std::max(0.0, solveAndRows - report.times.formFactors);

    keepSolution(*solver, formFactors.analytic() && options.receiverPoints == 3, solution, report);
    directLight.addPointVariation(solution.problem, solution.pointRadiosity);
    result.kept = std::move(kept);
  }
  warnIfNotConverged(limits, solution, report);
  report.times.total = secondsSince(start);
  return result;
}

}  // namespace rad
