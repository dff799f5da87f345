#include "radiosity/pipeline/row_solve.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "radiosity/core/interrupt.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/refinement_stage.h"
#include "radiosity/pipeline/shadow_ray_direct_irradiance.h"
#include "radiosity/pipeline/solver_results.h"
#include "radiosity/solvers/solver_factory.h"

namespace rad {
namespace {

// Solves, and while adaptive refinement splits elements of the converged solution, solves on.
void solveAndRefine(const SolveSetup& setup, Solver& solver, FormFactorStage& formFactors,
                    DirectLightStage& directLight, Solution& solution, SolveReport& report) {
  const SolveOptions& options = setup.options;
  const bool keepTerms = options.keepBounceTerms && options.solver == SolverKind::Jacobi;
  AdaptiveRefinement refinement(options, *solution.mesh);
  for (int pass = 0;; ++pass) {
    report.stoppedBy = iterate(solver, setup.limits, keepTerms ? &solution.bounceTerms : nullptr);
    report.converged = converged(report.stoppedBy);
    if (!report.converged ||
        !refinement.refine(pass, solution, formFactors, directLight, solver, report))
      break;
  }
  refinement.finish(report);
}

}  // namespace

std::shared_ptr<KeptFactors> solveByRows(const SolveSetup& setup, Solution& solution,
                                         SolveReport& report) {
  const SolveOptions& options = setup.options;
  DirectLightStage directLight(solution.scene, *solution.mesh, setup.rays, options,
                               &setup.exposure);
  std::shared_ptr<KeptFactors> kept;
  std::vector<int> rayMultipliers;  // empty: from the problem's emission
  if (options.keepFactors)
    kept = keepLightsApart(solution, setup.rays, options, setup.exposure, setup.elementEdge,
                           rayMultipliers, report);
  else
    directLight.apply(solution.problem);  // the lights' first shot: ρ E_d joins the emission
  noteBlackElements(solution, report);
  FormFactorStage formFactors(solution.scene, *solution.mesh, setup.rays, solution.problem, options,
                              &setup.exposure, std::move(rayMultipliers));
  throwIfInterrupted();

  const auto t = std::chrono::steady_clock::now();
  const std::unique_ptr<Solver> solver =
      makeSolver(options.solver, solution.problem, formFactors.shots(),
                 [&] { return formFactors.gatheringMatrix(); });
  solveAndRefine(setup, *solver, formFactors, directLight, solution, report);
  const double solveAndRows = secondsSince(t);
  if (kept) kept->rows = KeptRowTable(formFactors.takeAllRows());  // those shooting never read too
  formFactors.report(report, options.solver);
  if (!kept) directLight.report(report);
  report.times.solve = std::max(0.0, solveAndRows - report.times.formFactors);

  const std::vector<Rgb> lights = kept ? keptLightsIrradiance(*kept) : directLight.irradiance();
  keepSolverResults(*solver, keepsPointValues(options), lights, solution, report);
  if (solution.directIrradiance.empty())  // rows through mirrors and glass
    solution.directIrradiance = directIrradianceByShadowRays(
        solution, solution.problem, lights, setup.rays, setup.exposure, options, report.raysCast);
  directLight.addPointVariation(solution.problem, solution.pointRadiosity);
  return kept;
}

}  // namespace rad
