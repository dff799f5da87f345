#include "radiosity/pipeline/light_group_solve.h"

#include <algorithm>
#include <string>

#include "radiosity/core/log.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/solvers/progressive_solver.h"
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
  // B at the receiver points where the whole solve would keep them (keepSolution's rule).
  const bool pointValues = formFactors.analytic() && options.receiverPoints == 3;
  solution.layers.clear();
  report.iterations = 0;
  report.finalProgress = 0;
  report.converged = true;
  report.stoppedBy = StopReason::Tolerance;
  bool anyShooting = false;
  std::vector<Rgb> unshot(n);
  for (LightGroupProblem& g : groups) {
    logInfo("light group '" + g.group.name + "'");
    const std::unique_ptr<Solver> solver =
        makeSolver(options.solver, g.problem, formFactors.shots(),
                   [&] { return formFactors.gatheringMatrix(); });
    const StopReason stopped = iterate(*solver, limits);
    LightLayer layer;
    layer.group = g.group;
    layer.radiosity = solver->solution();
    const auto* shooting = dynamic_cast<const ProgressiveSolver*>(solver.get());
    if (shooting && pointValues) {
      layer.pointRadiosity = shooting->pointSolution();
      if (g.directLight) g.directLight->addPointVariation(g.problem, layer.pointRadiosity);
    }
    if (shooting) {
      anyShooting = true;
      const std::vector<Rgb> own = shooting->unshotPowerOfElements();
      for (int e = 0; e < n; ++e) unshot[e] += own[e];
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
  uint64_t rays = 0;
  for (const LightGroupProblem& g : groups)
    if (g.directLight) rays += g.directLight->raysCast();
  report.directLightRays = rays;
}

}  // namespace rad
