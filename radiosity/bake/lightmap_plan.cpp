#include "radiosity/bake/lightmap_plan.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <sstream>

#include "meshing/lightmap_charts.h"
#include "meshing/mesh_uv_layout.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/pipeline/resource_limits.h"

namespace rad {

LaidOutLightmap layoutLightmap(const PatchMesh& mesh, const LightmapLayoutSpec& o,
                               const std::string& scenePath) {
  const double asked = o.texelSize > 0 ? o.texelSize : o.texelDensity > 0 ? 1 / o.texelDensity : 0;
  const bool onePage = o.lightmapSize > 0 && asked == 0;
  const double texelSize = onePage ? 0 : asked > 0 ? asked : defaultTexelSize(mesh);
  const int maxPage = o.lightmapSize > 0 ? o.lightmapSize : kDefaultMaxLightmapPage;
  std::ostringstream why;
  if (onePage)
    why << "--lightmap-size " << o.lightmapSize << ": the densest texels that fit one page";
  else if (asked > 0)
    why << (o.texelSize > 0 ? "--texel-size" : "--texel-density") << ", pages of at most "
        << maxPage << "²";
  else
    why << "default: " << formatNumber(kDefaultLightmapTexels) << " texels over the scene's "
        << formatNumber(kDefaultLightmapTexels * texelSize * texelSize)
        << " units² of surface, pages of at most " << maxPage << "²";
  try {
    if (o.sceneUvs) {
      int side = o.lightmapSize;
      if (asked > 0)
        side = atlasSideForTexelSize(mesh, asked, o.lightmapSize > 0 ? o.lightmapSize : 16384);
      else if (!onePage)
        side = std::min(kDefaultMaxLightmapPage,
                        atlasSideForTexelSize(mesh, texelSize, std::numeric_limits<int>::max()));
      return {layoutFromMeshUvs(mesh, side, side, o.padding), why.str()};
    }
    return {packLightmapCharts(buildLightmapCharts(mesh, {o.chartAngle}),
                               {texelSize, onePage ? o.lightmapSize : 0, o.padding, maxPage}),
            why.str()};
  } catch (const InputError& e) {
    // The options do not fit this scene's charts: name the scene.
    if (!e.file().empty()) throw;
    throw InputError(scenePath, 0, e.what());
  }
}

LightmapPlan planLightmap(const Scene& scene, const SolveOptions& options,
                          const LightmapLayoutSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  checkSceneLimits(scene);  // as the solve does before it meshes
  const LaidOutLightmap planned =
      layoutLightmap(*meshScene(scene, options).mesh, spec, options.scenePath);
  LightmapPlan plan;
  if (!(options.refineThreshold > 0)) plan.laidOut = planned;
  plan.seconds = secondsSince(start);
  const LightmapLayout& l = planned.layout;
  logInfo("lightmap plan: " + std::to_string(l.rects.size()) + " charts on " +
          std::to_string(l.pages) + " page(s) of " + std::to_string(l.width) + "×" +
          std::to_string(l.height) + ", " + formatNumber(1 / l.texelSize) +
          " texels per scene unit (" + planned.rule + ")");
  return plan;
}

}  // namespace rad
