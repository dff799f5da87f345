#include "radiosity/render/radiosity_integrator.h"

#include "radiosity/render/direct_indirect_split.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/interpolated_preview.h"

namespace rad {

std::unique_ptr<Integrator> makeRadiosityIntegrator(const RenderScene& scene,
                                                    const std::vector<Rgb>& radiosity,
                                                    const std::vector<Rgb>& directIrradiance,
                                                    FinalGatherOptions options) {
  if (options.gatherRays > 0) return std::make_unique<FinalGather>(scene, radiosity, options);
  if (options.indirectFromSolution())
    return std::make_unique<DirectIndirectSplit>(scene, radiosity, directIrradiance,
                                                 options.lightRays);
  return std::make_unique<InterpolatedPreview>(scene, radiosity);
}

}  // namespace rad
