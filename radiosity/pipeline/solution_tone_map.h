#pragma once

#include "radiosity/output/tone_map.h"
#include "radiosity/pipeline/solution.h"

namespace rad {

// The auto exposure of a solution's displays (vertex colours, lightmaps, solution.vtp, the
// viewer): solutionToneMap (output/display_radiance.h) with the emitters taken from the
// materials (Ke > 0). Not from problem.emission: the lights' first shot (sun, sky, lamps) is held
// there too, and every directly lit element would count as an emitter and leave the exposure to
// the shadows.
ToneMap solutionToneMap(const Solution& solution);

}  // namespace rad
