#include "radiosity/pipeline/light_group_solve.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/shadow_ray_direct_irradiance.h"
#include "radiosity/pipeline/solver_results.h"
#include "radiosity/solvers/solver_factory.h"

namespace rad {

std::vector<LightGroupProblem> makeLightGroupProblems(const Scene& scene, const PatchMesh& mesh,
                                                      const RayCaster& rays,
                                                      const SolveOptions& options,
                                                      const ElementExposure* exposure,
                                                      RadiosityProblem& base) {
  std::vector<LightGroupProblem> groups;
  for (LightGroup& group : lightGroups(scene)) {
    LightGroupProblem g;
    g.group = std::move(group);
    g.problem = base;
    std::vector<char> member(scene.materials.size(), 0);
    for (int m : g.group.materials) member[m] = 1;
    for (int e = 0; e < mesh.elementCount(); ++e)
      if (!member[mesh.material(e)]) g.problem.emission[e] = Rgb();
    if (!g.group.lights.empty()) {
      g.directLight =
          std::make_unique<DirectLightStage>(scene, mesh, rays, options, exposure, &g.group.lights);
      g.directLight->apply(g.problem);
    }
    groups.push_back(std::move(g));
  }
  for (Rgb& e : base.emission) e = Rgb();
  for (const LightGroupProblem& g : groups)
    for (int e = 0; e < base.size(); ++e) base.emission[e] += g.problem.emission[e];
  std::string names;
  for (const LightGroupProblem& g : groups) names += (names.empty() ? "" : ", ") + g.group.name;
  logInfo("light groups: " + std::to_string(groups.size()) + " (" + names + ")");
  return groups;
}

std::vector<int> lightGroupRayMultipliers(const std::vector<LightGroupProblem>& groups,
                                          const std::vector<double>& area) {
  std::vector<std::vector<Rgb>> power;
  for (const LightGroupProblem& g : groups) power.push_back(g.problem.emission);
  return sourceRayMultipliers(area, power);
}

void solveLightGroups(std::vector<LightGroupProblem>& groups, FormFactorStage& formFactors,
                      const SolveOptions& options, const IterationLimits& limits,
                      Solution& solution, SolveReport& report) {
  const int n = solution.mesh->elementCount();
  const bool pointValues = keepsPointValues(options);
  solution.layers.clear();
  report.iterations = 0;
  report.finalProgress = 0;
  report.converged = true;
  report.stoppedBy = StopReason::Tolerance;
  bool anyShooting = false;
  std::vector<Rgb> unshot(n), direct(n);  // the groups' sums
  bool separable = true;
  for (LightGroupProblem& g : groups) {
    logInfo("light group '" + g.group.name + "'");
    const std::unique_ptr<Solver> solver =
        makeSolver(options.solver, g.problem, formFactors.shots(),
                   [&] { return formFactors.gatheringMatrix(); });
    const StopReason stopped = iterate(*solver, limits);
    SolverResults results = readSolverResults(*solver, pointValues);
    const std::vector<Rgb> groupDirect =
        directIrradianceOf(*solver, solution, g.problem,
                           g.directLight ? g.directLight->irradiance() : std::vector<Rgb>());
    if (groupDirect.empty()) separable = false;  // rows through mirrors and glass
    for (size_t e = 0; e < groupDirect.size(); ++e) direct[e] += groupDirect[e];
    LightLayer layer;
    layer.group = g.group;
    layer.radiosity = std::move(results.radiosity);
    layer.pointRadiosity = std::move(results.pointRadiosity);
    if (g.directLight && !layer.pointRadiosity.empty())
      g.directLight->addPointVariation(g.problem, layer.pointRadiosity);
    if (!results.unshot.empty()) {
      anyShooting = true;
      for (int e = 0; e < n; ++e) unshot[e] += results.unshot[e];
    }
    report.solverName = solver->name();
    report.progressMeasure = solver->progressMeasure();
    report.iterations += solver->iterations();
    report.finalProgress = std::max(report.finalProgress, solver->progress());
    if (!converged(stopped)) {
      report.converged = false;
      report.stoppedBy = stopped;
    } else if (report.converged) {
      report.stoppedBy = stopped;
    }
    solution.layers.push_back(std::move(layer));
  }
  // The whole solution is the layers' sum (so they add up to it exactly).
  solution.radiosity.assign(n, Rgb());
  solution.pointRadiosity.assign(pointValues && anyShooting ? n : 0, {});
  for (const LightLayer& layer : solution.layers) {
    for (int e = 0; e < n; ++e) solution.radiosity[e] += layer.radiosity[e];
    if (layer.pointRadiosity.empty()) continue;
    for (int e = 0; e < static_cast<int>(solution.pointRadiosity.size()); ++e)
      for (int k = 0; k < 3; ++k) solution.pointRadiosity[e][k] += layer.pointRadiosity[e][k];
  }
  if (anyShooting) solution.unshot = std::move(unshot);
  if (separable) solution.directIrradiance = std::move(direct);
  uint64_t rays = 0;
  for (const LightGroupProblem& g : groups)
    if (g.directLight) rays += g.directLight->raysCast();
  report.directLightRays = rays;
}

void solveByLightGroups(const SolveSetup& setup, Solution& solution, SolveReport& report) {
  // One problem per light group over the same form factors; the whole is their sum.
  std::vector<LightGroupProblem> groups = makeLightGroupProblems(
      solution.scene, *solution.mesh, setup.rays, setup.options, &setup.exposure, solution.problem);
  noteBlackElements(solution, report);
  FormFactorStage formFactors(solution.scene, *solution.mesh, setup.rays, solution.problem,
                              setup.options, &setup.exposure,
                              lightGroupRayMultipliers(groups, solution.problem.area));
  throwIfInterrupted();
  const auto t = std::chrono::steady_clock::now();
  solveLightGroups(groups, formFactors, setup.options, setup.limits, solution, report);
  if (solution.directIrradiance.empty()) {  // rows through mirrors and glass
    std::vector<Rgb> lights(solution.mesh->elementCount());
    for (const LightGroupProblem& g : groups)
      if (g.directLight && !g.directLight->irradiance().empty())
        for (size_t e = 0; e < lights.size(); ++e) lights[e] += g.directLight->irradiance()[e];
    solution.directIrradiance =
        directIrradianceByShadowRays(solution, solution.problem, lights, setup.rays, setup.exposure,
                                     setup.options, report.raysCast);
  }
  const double solveAndRows = secondsSince(t);
  formFactors.report(report, setup.options.solver);
  report.times.solve = std::max(0.0, solveAndRows - report.times.formFactors);
}

}  // namespace rad
