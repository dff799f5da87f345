#pragma once

#include <array>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// What a solver reached, read back once its iterations stop (every solve, light group, relight
// and update reads it here): B per element, B at the receiver points where the rows resolve them,
// and the unshot power a shooting solver still holds.
struct SolverResults {
  std::vector<Rgb> radiosity;
  // B at each element's 3 receiver points: with `pointValues` (analytic factors with 3 receiver
  // points) from a shooting solver; empty otherwise.
  std::vector<std::array<Rgb, 3>> pointRadiosity;
  std::vector<Rgb> unshot;  // per element (W); empty for a gathering solver
};
// Whether the solution keeps B at the receiver points: analytic factors with 3 receiver points,
// where a shooting solver resolves them (the direct light's variation is added there too).
bool keepsPointValues(const SolveOptions& options);
SolverResults readSolverResults(const Solver& solver, bool pointValues);

// readSolverResults into the solution (radiosity, pointRadiosity, unshot), and the solver's
// name, measure, iterations and final progress into the report (reportSolver).
void keepSolverResults(const Solver& solver, bool pointValues, Solution& solution,
                       SolveReport& report);

}  // namespace rad
