#pragma once

#include <memory>

#include "radiosity/pipeline/kept_factors_stage.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_stages.h"

namespace rad {

// The row strategy of solveScene (every solver but the hierarchical one, without light groups):
// the lights' first shot (DirectLightStage; with --keep-factors each light's on its own,
// keepLightsApart), the form factors (FormFactorStage: hemisphere rows or analytic patch shots),
// the solver from makeSolver stepped to its limits, ⇄ adaptive refinement between solves, and
// what it reached kept in the solution. Returns the kept factors with their rows with
// --keep-factors, else null.
std::shared_ptr<KeptFactors> solveByRows(const SolveSetup& setup, Solution& solution,
                                         SolveReport& report);

}  // namespace rad
