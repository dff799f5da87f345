#include "radiosity/pipeline/hierarchical_solve.h"

#include <algorithm>
#include <chrono>

#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/hierarchical/hierarchical_radiosity.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/emitter_first_shot.h"
#include "radiosity/pipeline/shadow_ray_direct_irradiance.h"
#include "radiosity/pipeline/solver_results.h"

namespace rad {
using Clock = std::chrono::steady_clock;

void solveHierarchical(const SolveOptions& options, const RayCaster& rays,
                       const ElementExposure& exposure, const IterationLimits& limits,
                       Solution& solution, SolveReport& report) {
  if (solution.scene.hasSpecular())
    throw InputError(
        "--solver hierarchical does not follow light through mirrors and glass yet (its link "
        "rays stop at their first hit): use --solver gauss-seidel or progressive for this scene");
  auto t = Clock::now();
  HierarchicalOptions hierarchical;
  hierarchical.linkEpsilon = options.linkEpsilon;
  hierarchical.raysPerReceiver = options.raysPerElement;
  hierarchical.seed = options.seed;
  hierarchical.exposure = &exposure;
  HierarchicalRadiosity hr(*solution.mesh, rays, solution.problem, hierarchical);
  report.times.formFactors += secondsSince(t);
  const NodeHierarchy& tree = hr.tree();
  logInfo("hierarchy: " + std::to_string(tree.size()) + " nodes (" +
          std::to_string(tree.clusterCount()) + " clusters, depth " + std::to_string(tree.depth()) +
          "), " + std::to_string(hr.links().size()) + " links from " +
          std::to_string(hr.links().receivers().size()) + " receivers");
  throwIfInterrupted();
  for (;;) {
    report.stoppedBy = iterate(hr.solver(), limits);
    report.converged = converged(report.stoppedBy);
    if (!report.converged || hr.passes() >= kMaxLinkPasses) break;
    t = Clock::now();
    const int64_t split = hr.refineLinks();
    report.times.formFactors += secondsSince(t);
    if (split == 0) break;
    logInfo("links refined: " + std::to_string(split) + " split, " +
            std::to_string(hr.links().size()) + " links");
    throwIfInterrupted();
  }
  solution.radiosity = hr.solver().solution();
  if (options.keepLinks) solution.links = std::make_shared<const ElementLinks>(hr);
  reportSolver(hr.solver(), report);
  SolveReport::Hierarchy& h = report.hierarchy;
  h.nodes = tree.size();
  h.clusters = tree.clusterCount();
  h.depth = tree.depth();
  h.links = hr.links().size();
  h.receivers = static_cast<int>(hr.links().receivers().size());
  h.linkPasses = hr.passes();
  h.linksRefined = hr.linksRefined();
  h.treeBytes = static_cast<int64_t>(tree.bytes());
  h.linkBytes = static_cast<int64_t>(hr.links().bytes());
  h.solverBytes = static_cast<int64_t>(hr.solver().bytes());
  report.raysCast += hr.raysCast();
  report.rowsComputed = h.receivers;
  report.shooters = h.receivers;
}

namespace {

// E_d for a hierarchical solve (Solution::directIrradiance): the lights' first shot plus the
// emitters' direct light by the shadow rays of their first shot, the very D the links were solved
// with when every emitter was shot; when the links carry some emitters (large ones), all of them
// by a second estimate of the same kind (directIrradianceByShadowRays), which the solve does not
// use. 0 on black elements.
std::vector<Rgb> linksDirectIrradiance(const SolveSetup& setup, const EmitterFirstShot& shot,
                                       const DirectLightStage& lights, const Solution& solution,
                                       SolveReport& report) {
  const std::vector<Rgb> own = ownEmission(solution, solution.problem, lights.irradiance());
  const int emitting = static_cast<int>(
      std::count_if(own.begin(), own.end(), [](const Rgb& e) { return e.maxComponent() > 0; }));
  if (shot.emitters() != emitting)
    return directIrradianceByShadowRays(solution, solution.problem, lights.irradiance(), setup.rays,
                                        setup.exposure, setup.options, report.raysCast);
  const int n = solution.mesh->elementCount();
  std::vector<Rgb> direct = shot.active() ? shot.irradiance() : std::vector<Rgb>(n);
  const std::vector<Rgb>& fromLights = lights.irradiance();
  for (int e = 0; e < n; ++e) {
    if (!fromLights.empty()) direct[e] += fromLights[e];
    if (solution.problem.reflectance[e].maxComponent() <= 0) direct[e] = Rgb();
  }
  return direct;
}

}  // namespace

void solveByLinks(const SolveSetup& setup, Solution& solution, SolveReport& report) {
  const SolveOptions& options = setup.options;
  DirectLightStage directLight(solution.scene, *solution.mesh, setup.rays, options,
                               &setup.exposure);
  EmitterFirstShot emitterShot(*solution.mesh, setup.rays, setup.exposure, options.seed,
                               EmitterFirstShot::raysForSolve(options.raysPerElement));
  auto t = Clock::now();
  emitterShot.apply(solution.problem);
  const double emitterSeconds = secondsSince(t);  // form-factor time, added after the solve's
  report.raysCast += emitterShot.raysCast();
  if (emitterShot.active())
    logInfo("emitters' direct light: " + std::to_string(emitterShot.emitters()) +
            " emitting elements, " + std::to_string(emitterShot.raysCast()) + " shadow rays, " +
            formatNumber(emitterSeconds) + " s");
  directLight.apply(solution.problem);  // the lights' first shot: ρ E_d joins the emission
  noteBlackElements(solution, report);
  t = Clock::now();
  solveHierarchical(options, setup.rays, setup.exposure, setup.limits, solution, report);
  emitterShot.restore(solution.problem, solution.radiosity);
  solution.directIrradiance =
      linksDirectIrradiance(setup, emitterShot, directLight, solution, report);
  directLight.report(report);
  report.times.solve = std::max(0.0, secondsSince(t) - report.times.formFactors);
  report.times.formFactors += emitterSeconds;
}

}  // namespace rad
