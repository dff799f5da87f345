#pragma once

#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// E_d (Solution::directIrradiance) where the solver's own factors cannot give it: the lights'
// first shot `lightsIrradiance` (one per element, or empty) plus every emitter's direct light by
// the shadow rays of EmitterFirstShot (every emitter shot, however large; half --rays per element),
// on the problem's emission less the lights' ρ E_d; 0 on black elements. For a hierarchical
// solve's links, and for rows that follow light through mirrors and glass (which mix the light an
// emitter sends through them into its row, where the split's shadow rays do not follow it).
// `raysCast` gains the rays.
std::vector<Rgb> directIrradianceByShadowRays(const Solution& solution,
                                              const RadiosityProblem& problem,
                                              const std::vector<Rgb>& lightsIrradiance,
                                              const RayCaster& rays,
                                              const ElementExposure& exposure,
                                              const SolveOptions& options, uint64_t& raysCast);

}  // namespace rad
