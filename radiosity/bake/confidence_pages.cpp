#include "radiosity/bake/confidence_pages.h"

#include <tbb/parallel_invoke.h>

#include <chrono>
#include <cmath>

#include "radiosity/bake/texel_evaluation.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/lightmap_confidence.h"
#include "radiosity/scene/surface_textures.h"

namespace rad {

std::vector<Lightmap> confidencePages(const Solution& solution, const LightmapLayout& layout,
                                      const std::vector<Lightmap>& lightmaps,
                                      LightmapContent content,
                                      const std::vector<std::vector<Rgb>>& gatherError,
                                      const ElementExposure& exposure) {
  const PatchMesh& mesh = *solution.mesh;
  const Scene& scene = solution.scene;
  const bool irradiance = content == LightmapContent::Irradiance;
  const bool textured = texelsFromIncidentLight(scene, content);
  const int n = mesh.elementCount();
  std::vector<Rgb> radianceError, incidentError;
  if (gatherError.empty()) {
    std::vector<Rgb> radiance(n);
    for (int e = 0; e < n; ++e) radiance[e] = solution.radiosity[e] / M_PI;
    std::vector<std::array<Rgb, 3>> points = solution.pointRadiosity;
    for (auto& p : points)
      for (Rgb& b : p) b = b / M_PI;
    // The two estimates side by side (each walks the mesh's corners per channel).
    tbb::parallel_invoke([&] { radianceError = displayedError(mesh, radiance, points); },
                         [&] {
                           if (!textured) return;
                           std::vector<Rgb> incident(n);
                           for (int e = 0; e < n; ++e)
                             incident[e] = incidentLight(solution.radiosity[e],
                                                         M_PI * elementEmission(scene, mesh, e),
                                                         solution.problem.reflectance[e]) /
                                           M_PI;
                           incidentError = displayedError(mesh, incident);
                         });
  }
  auto overRho = [](Rgb v, const Rgb& rho) {
    for (int c = 0; c < 3; ++c) v[c] = rho[c] > 0 ? v[c] / rho[c] : 0;
    return v;
  };
  std::vector<Lightmap> pages;
  for (int page = 0; page < layout.pages; ++page)
    pages.push_back(bakeOnTexels(
        lightmaps[page], layout, [&](int e, const Eigen::Vector3d& b, size_t texel) -> Rgb {
          if (!gatherError.empty()) {
            const Rgb& error = gatherError[page][texel];
            return irradiance ? overRho(error, reflectanceAt(scene, mesh, e, b[1], b[2])) : error;
          }
          // Buried: exactly the texel's own emission (no light arrives), nothing to be wrong about.
          if (exposure.buriedAtBarycentric(e, b[1], b[2])) return Rgb();
          if (irradiance) return incidentError[e];
          if (textured && hasReflectanceTexture(scene, mesh, e))
            return reflectanceAt(scene, mesh, e, b[1], b[2]) * incidentError[e];
          return radianceError[e];
        }));
  return pages;
}

std::vector<Lightmap> bakeConfidence(const Solution& solution, const LightmapLayout& layout,
                                     const std::vector<Lightmap>& lightmaps, const BakeSpec& spec,
                                     const std::vector<std::vector<Rgb>>& gatherError,
                                     const ElementExposure& exposure, BakeReport& report) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Lightmap> pages =
      confidencePages(solution, layout, lightmaps, spec.content, gatherError, exposure);
  BakeReport::Confidence& c = report.confidence.emplace();
  c.summary = summariseConfidence(lightmaps, pages);
  c.includes = spec.gather.gatherRays > 0
                   ? "the per-texel gather's Monte Carlo standard error (shadow and gather rays)"
               : spec.gather.indirectFromSolution()
                   ? "the per-texel direct light's Monte Carlo standard error (shadow rays; the "
                     "indirect part is the solution's, interpolated)"
                   : "the mesh's displayed error (the interpolated values against the "
                     "solution, the refinement's estimate)";
  logInfo("lightmap confidence: " + describeConfidence(c.summary) + "; " + c.includes);
  c.seconds = secondsSince(start);
  return pages;
}

}  // namespace rad
