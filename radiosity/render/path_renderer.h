#pragma once

#include <vector>

#include "radiosity/render/image_renderer.h"
#include "radiosity/render/path_integrator.h"

namespace rad {

// The full image and, with a binning, one image per bin (its paths' contributions only).
struct PathRenderOutput {
  RenderOutput full;
  std::vector<RenderOutput> bins;  // image and variance; rays and seconds are in `full`
};

// renderImage for path integrators: the same pixels, samples and random streams (so `full`
// equals renderImage's image for integrators that splat nothing), plus the binned images and
// the light-tracing splats, divided by the samples per pixel. A pixel's variance adds the
// splats' (Σv² − (Σv)²/N over the N camera samples of the image, each one light path).
PathRenderOutput renderPathImage(const Camera& camera, const PathIntegrator& integrator,
                                 const RenderSettings& settings, const PathBinning* binning);

}  // namespace rad
