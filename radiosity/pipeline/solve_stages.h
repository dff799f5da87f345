#pragma once

#include "radiosity/pipeline/element_size.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/pipeline/thread_limit.h"
#include "radiosity/solvers/solver.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The stages that the composing functions share: solveScene's (solve_pipeline.h), relight's and
// update's. Each is one named step of them.

// The threads a solve runs on (--threads, or every core for 0) into report.threads; TBB held to
// them while the returned limit lives.
ThreadLimit limitSolveThreads(const SolveOptions& options, SolveReport& report);

// meshScene of solution.scene into solution.mesh; the element size, its rule and the element
// count before refinement into the report, with the time; one log line. Returns the sizing.
ElementSizing meshStage(Solution& solution, const SolveOptions& options, SolveReport& report);

// Notes the elements of reflectance 0 that are not mirrors or glass: they pass no light on.
void noteBlackElements(const Solution& solution, SolveReport& report);

// Steps the solver to its limits (iterate), then keeps what it reached (keepSolverResults, with
// the lights' first shot `lightsIrradiance`): the stopping state, B, E_d and the solver's fields
// into the solution and the report.
void solveToLimits(Solver& solver, const IterationLimits& limits, bool pointValues,
                   const std::vector<Rgb>& lightsIrradiance, Solution& solution,
                   SolveReport& report);

// What each solve strategy (row solve, hierarchical, light groups) works with: solveScene
// makes it once, after the mesh, the rays, the buried parts and the problem.
struct SolveSetup {
  const SolveOptions& options;
  const RayCaster& rays;
  const ElementExposure& exposure;
  IterationLimits limits;
  double elementEdge;  // the mesh's element size S (kept factors record it)
};

}  // namespace rad
