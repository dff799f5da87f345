#pragma once

#include <vector>

#include "radiosity/render/render_scene.h"
#include "radiosity/scene/camera.h"

namespace rad {

// Which pixels of a camera image set its auto exposure (ToneMap::autoExposure's weights, one per
// pixel, row by row): 1 where the primary ray through the pixel's centre (from the lens centre)
// hits a surface that does not emit, 0 where it hits an emitter or escapes to the sky. Emitters
// and the sky are far brighter than the surfaces they light: left in, a lamp in view would set
// the exposure and leave the room it lights nearly black. Empty when no pixel sees a lit surface
// (then every pixel counts alike).
std::vector<double> exposureWeights(const Camera& camera, const RenderScene& scene);

}  // namespace rad
