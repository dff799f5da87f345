#include "radiosity/bake/directional_pages.h"

#include <chrono>

#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"

namespace rad {

std::vector<DirectionalLightmapPage> bakeDirectionalPages(
    const RenderScene& view, const Solution& solution, const LightmapLayout& layout,
    const VertexInterpolation& interpolation, const BakeSpec& spec, BakeReport& report) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<DirectionalLightmapPage> pages;
  for (int page = 0; page < layout.pages; ++page)
    pages.push_back(bakeDirectionalPage(view, solution.radiosity, layout, interpolation,
                                        spec.dilation, page, spec.directionalRays, spec.seed));
  const double seconds = secondsSince(start);
  report.directional = BakeReport::Directional{spec.directionalRays, layout.pages, seconds};
  logInfo("directional lightmap: L1 SH of the incident light, " +
          std::to_string(spec.directionalRays) + " rays per texel, " + formatNumber(seconds) +
          " s");
  return pages;
}

}  // namespace rad
