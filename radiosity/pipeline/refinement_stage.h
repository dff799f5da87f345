#pragma once

#include "meshing/adaptive_refinement.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// Adaptive refinement between solves (--refine-threshold): after a converged solve, split the
// elements where the displayed radiance departs most from the solution or an emitter's shadow
// boundary crosses, up to the pass's share of the element budget; the new elements gather what
// was already shot and shooting carries on. Needs a RefinableSolver and analytic form factors
// (validateSolveOptions makes sure of both).
class AdaptiveRefinement {
 public:
  AdaptiveRefinement(const SolveOptions& options, const PatchMesh& uniformMesh);

  // Refinement pass `pass` (0-based) on a converged solution: true when elements were split and
  // the problem, the form factors and the solver were updated, so the solve goes on; false when
  // refinement is off or over (passes done, nothing to split, or the budget reached).
  // The lights' first shot is recomputed on the split elements.
  bool refine(int pass, Solution& solution, FormFactorStage& formFactors,
              DirectLightStage& directLight, Solver& solver, SolveReport& report);
  // Notes in the report what the last pass left unsplit.
  void finish(SolveReport& report) const;

 private:
  bool enabled_ = false;
  int passes_ = 0;
  int startElements_ = 0;
  int receiverPoints_ = 3;
  RefinementOptions options_;
  int unrefined_ = -1;  // elements the last refinement pass left alone
};

}  // namespace rad
