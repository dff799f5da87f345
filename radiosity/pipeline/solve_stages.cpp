#include "radiosity/pipeline/solve_stages.h"

#include <chrono>
#include <string>

#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/solver_results.h"

namespace rad {
ThreadLimit limitSolveThreads(const SolveOptions& options, SolveReport& report) {
  report.threads = threadCount(options.threads);
  return ThreadLimit(options.threads);
}

ElementSizing meshStage(Solution& solution, const SolveOptions& options, SolveReport& report) {
  const auto t = std::chrono::steady_clock::now();
  MeshedScene meshed = meshScene(solution.scene, options);
  solution.mesh = std::move(meshed.mesh);
  report.maxArea = meshed.maxArea;
  report.elementSize = meshed.sizing.edge;
  report.elementSizeRule = elementSizeRuleName(meshed.sizing.rule);
  report.elementsBeforeRefinement = solution.mesh->elementCount();
  report.times.mesh = secondsSince(t);
  logInfo("mesh: " + std::to_string(solution.mesh->patchCount()) + " patches, " +
          std::to_string(solution.mesh->elementCount()) + " elements (element size " +
          formatNumber(report.elementSize) + ", set by " +
          (meshed.sizing.rule == ElementSizeRule::SceneDefault
               ? std::string("the scene's extent and area")
               : "--" + report.elementSizeRule) +
          ", max area " + formatNumber(report.maxArea) + ")");
  return meshed.sizing;
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

void solveToLimits(Solver& solver, const IterationLimits& limits, bool pointValues,
                   const std::vector<Rgb>& lightsIrradiance, Solution& solution,
                   SolveReport& report) {
  report.stoppedBy = iterate(solver, limits);
  report.converged = converged(report.stoppedBy);
  keepSolverResults(solver, pointValues, lightsIrradiance, solution, report);
}

}  // namespace rad
