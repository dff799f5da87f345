#pragma once

#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// How every output shows a radiosity solution: a Lambertian surface of radiosity B (W/m²) has
// outgoing radiance L = B/π (W·m⁻²·sr⁻¹), and the display exposure is auto exposure over the
// elements' radiance weighted by their area. Vertex colours, lightmaps, solution.vtp and the
// viewer all use these two, so their colours agree.
std::vector<Rgb> radianceFromRadiosity(const std::vector<Rgb>& radiosity);
ToneMap solutionToneMap(const std::vector<Rgb>& radiosity, const std::vector<double>& area);

}  // namespace rad
