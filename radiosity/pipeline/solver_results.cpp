#include "radiosity/pipeline/solver_results.h"

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

void keepSolverResults(const Solver& solver, bool pointValues, Solution& solution,
                       SolveReport& report) {
  SolverResults results = readSolverResults(solver, pointValues);
  solution.radiosity = std::move(results.radiosity);
  solution.pointRadiosity = std::move(results.pointRadiosity);
  solution.unshot = std::move(results.unshot);
  reportSolver(solver, report);
}

}  // namespace rad
