#include "radiosity/pipeline/solver_results.h"

#include "radiosity/core/check.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/solvers/progressive_solver.h"

namespace rad {

bool keepsPointValues(const SolveOptions& options) {
  return options.formFactors == FormFactorMethod::Analytic && options.receiverPoints == 3;
}

SolverResults readSolverResults(const Solver& solver, bool pointValues) {
  SolverResults results;
  results.radiosity = solver.solution();
  if (const auto* shooting = dynamic_cast<const ProgressiveSolver*>(&solver)) {
    if (pointValues) results.pointRadiosity = shooting->pointSolution();
    results.unshot = shooting->unshotPowerOfElements();
  }
  return results;
}

std::vector<Rgb> ownEmission(const Solution& solution, const RadiosityProblem& problem,
                             const std::vector<Rgb>& lightsIrradiance) {
  const int n = problem.size();
  RAD_CHECK(lightsIrradiance.empty() || lightsIrradiance.size() == static_cast<size_t>(n));
  std::vector<Rgb> own(n);
  for (int e = 0; e < n; ++e)
    if (solution.scene.materials[solution.mesh->material(e)].isEmitter())
      own[e] = problem.emission[e] -
               (lightsIrradiance.empty() ? Rgb() : problem.reflectance[e] * lightsIrradiance[e]);
  return own;
}

std::vector<Rgb> directIrradianceOf(Solver& solver, const Solution& solution,
                                    const RadiosityProblem& problem,
                                    const std::vector<Rgb>& lightsIrradiance) {
  if (solution.scene.hasSpecular()) return {};
  const int n = problem.size();
  const auto lights = [&](int e) { return lightsIrradiance.empty() ? Rgb() : lightsIrradiance[e]; };
  std::vector<Rgb> irradiance =
      solver.irradianceFrom(ownEmission(solution, problem, lightsIrradiance));
  if (irradiance.empty()) return {};
  for (int e = 0; e < n; ++e)
    irradiance[e] = problem.reflectance[e].maxComponent() > 0 ? irradiance[e] + lights(e) : Rgb();
  return irradiance;
}

void keepSolverResults(Solver& solver, bool pointValues, const std::vector<Rgb>& lightsIrradiance,
                       Solution& solution, SolveReport& report) {
  SolverResults results = readSolverResults(solver, pointValues);
  solution.radiosity = std::move(results.radiosity);
  solution.pointRadiosity = std::move(results.pointRadiosity);
  solution.unshot = std::move(results.unshot);
  solution.directIrradiance =
      directIrradianceOf(solver, solution, solution.problem, lightsIrradiance);
  reportSolver(solver, report);
}

}  // namespace rad
