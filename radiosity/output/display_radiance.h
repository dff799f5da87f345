#pragma once

#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// How every output shows a radiosity solution: a Lambertian surface of radiosity B (W/m²) has
// outgoing radiance L = B/π (W·m⁻²·sr⁻¹), and the display exposure is auto exposure over the
// lit surfaces' radiance weighted by their area: emitters (emission > 0) take no part, so a large
// bright emitter cannot set the exposure and leave the scene it lights nearly black (unless every
// element emits). Vertex colours, lightmaps, solution.vtp and the viewer all use these two, so
// their colours agree.
std::vector<Rgb> radianceFromRadiosity(const std::vector<Rgb>& radiosity);
ToneMap solutionToneMap(const std::vector<Rgb>& radiosity, const std::vector<double>& area,
                        const std::vector<Rgb>& emission);

}  // namespace rad
