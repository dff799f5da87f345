#pragma once

// The confidence map of a baked lightmap (docs/baking.md, "How far to trust each texel"): per
// texel, the estimated absolute error of its value, and a summary over the covered texels.
#include <array>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/output/lightmap_bake.h"

namespace rad {

// Per element and channel, how far the field displayed over it (the linear interpolation of
// vertex means that the lightmap and the vertex colours show) may be from the solution: the
// refinement's own estimate, displayedVariation (meshing/adaptive_refinement.h) of each channel of
// `perElement`, or displayedPointError of each channel of `atPoints` when it is not empty (a
// solve with receiver points, whose vertex values come from the points). Same unit as the values;
// about 0 where the field is linear (a furnace, a uniform wall).
std::vector<Rgb> displayedError(const PatchMesh& mesh, const std::vector<Rgb>& perElement,
                                const std::vector<std::array<Rgb, 3>>& atPoints = {});

// The lightmap's "error" EXR channel of one page: the Rec. 709 luminance of the per-channel
// error estimate held in `error.radiance` (W·m⁻²·sr⁻¹, like the texels' luminance).
std::vector<float> errorChannel(const Lightmap& error);

// Over the covered texels (centre inside an element) whose value has a positive luminance: the
// relative error, estimate / value (luminances), at its median and 95th percentile, and the
// share of those texels above 10%. `values` and `errors` are the same pages.
struct ConfidenceSummary {
  size_t texels = 0;
  double medianRelative = 0, p95Relative = 0, fractionAbove10Percent = 0;
};
ConfidenceSummary summariseConfidence(const std::vector<Lightmap>& values,
                                      const std::vector<Lightmap>& errors);
// "median relative error 1.2%, 95th percentile 6.3%, 2.1% of covered texels above 10%".
std::string describeConfidence(const ConfidenceSummary& summary);

}  // namespace rad
