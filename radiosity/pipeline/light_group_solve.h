#pragma once

#include <memory>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/pipeline/solve_stages.h"
#include "radiosity/scene/light_groups.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// One light group's share of the problem: E_g = the emission of its emissive materials plus
// ρ E_d of its lights (their first shot); reflectance and area are the whole problem's.
struct LightGroupProblem {
  LightGroup group;
  RadiosityProblem problem;
  std::unique_ptr<DirectLightStage> directLight;  // null when the group has no lights
};

// The scene's light groups (scene/light_groups.h) as problems over `mesh`, from `base`
// (makeProblem: the materials' emission, no lights yet). Sets base.emission to the sum of the
// groups' emission, so the whole problem is the layers' sum by construction.
std::vector<LightGroupProblem> makeLightGroupProblems(const Scene& scene, const PatchMesh& mesh,
                                                      const RayCaster& rays,
                                                      const SolveOptions& options,
                                                      const ElementExposure* exposure,
                                                      RadiosityProblem& base);

// The rays each emitter row gets (emitterRayMultipliers) from its largest share of any one
// group's power: scaling a group's emission leaves every row, and so the other layers, unchanged.
std::vector<int> lightGroupRayMultipliers(const std::vector<LightGroupProblem>& groups,
                                          const std::vector<double>& area);

// Solves every group with its own solver over the shared form factors (rows computed once, cached)
// and keeps each layer in solution.layers; solution.radiosity, pointRadiosity and unshot are their
// sums. The radiosity system is linear in E, so the layers add up to the whole scene's solution
// (each to the solver's tolerance). Fills the report's solver fields: iterations summed, the
// largest final progress, converged only when every group did.
void solveLightGroups(std::vector<LightGroupProblem>& groups, FormFactorStage& formFactors,
                      const SolveOptions& options, const IterationLimits& limits,
                      Solution& solution, SolveReport& report);

// The light-groups strategy of solveScene (--light-groups): the groups' problems
// (makeLightGroupProblems, instead of the one first shot), one FormFactorStage whose emitter rows
// get lightGroupRayMultipliers, and solveLightGroups over it. No refinement.
void solveByLightGroups(const SolveSetup& setup, Solution& solution, SolveReport& report);

}  // namespace rad
