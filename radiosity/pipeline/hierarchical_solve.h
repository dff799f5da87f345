#pragma once

#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/pipeline/solve_stages.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The most times the links are refined again after a solve (BF refinement); each pass only
// splits links, so the passes end sooner where the solution stops changing the oracle's answer.
constexpr int kMaxLinkPasses = 6;

// --solver hierarchical: hierarchical radiosity with clustering over solution.mesh and
// solution.problem (its emission already holding the lights' first shot). Builds the tree
// (NodeHierarchy), links every patch to the root through the oracle (LinkOracle, threshold
// --link-epsilon × emitted power / elements), casts each receiver's rays for its links' factors
// (LinkFormFactors), solves by Gauss–Seidel over the links (HierarchicalSolver) to the
// tolerance, then refines the links that the solved B makes carry too much and solves again,
// until none does or kMaxLinkPasses. The leaves are the elements: solution.radiosity is B per
// element, as with every solver. Refuses scenes with mirrors or glass (rays would continue).
void solveHierarchical(const SolveOptions& options, const RayCaster& rays,
                       const ElementExposure& exposure, const IterationLimits& limits,
                       Solution& solution, SolveReport& report);

// The hierarchical strategy of solveScene: its links would gather a small lamp's light by chance,
// so the emitters' direct light by shadow rays first (EmitterFirstShot: the problem becomes
// R = B − E), the lights' first shot (DirectLightStage), solveHierarchical, then B = R + E.
void solveByLinks(const SolveSetup& setup, Solution& solution, SolveReport& report);

}  // namespace rad
