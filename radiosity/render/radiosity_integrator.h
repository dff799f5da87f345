#pragma once

#include <memory>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/final_gather_options.h"
#include "radiosity/render/integrator.h"
#include "radiosity/render/render_scene.h"

namespace rad {

// The eye pass over a radiosity solution (`radiosity`: B per element) that `options` choose, the
// one place they decide it: gatherRays > 0, FinalGather; gatherRays 0 with lightRays,
// DirectIndirectSplit; neither, InterpolatedPreview. The two that cast rays per hit are also
// TexelRadiance (texel_radiance.h), for the bake. `directIrradiance`: E_d per element as the
// solve computed it (Solution::directIrradiance), which the split takes its indirect part with.
// Holds references to `scene` and to neither vector.
std::unique_ptr<Integrator> makeRadiosityIntegrator(const RenderScene& scene,
                                                    const std::vector<Rgb>& radiosity,
                                                    const std::vector<Rgb>& directIrradiance,
                                                    FinalGatherOptions options);

}  // namespace rad
