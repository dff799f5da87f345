#include "radiosity/pipeline/problem_setup.h"

#include <algorithm>
#include <cmath>

#include "radiosity/scene/coverage.h"
#include "radiosity/scene/surface_textures.h"

namespace rad {

RadiosityProblem makeProblem(const Scene& scene, const PatchMesh& mesh,
                             const ElementExposure* exposure) {
  RadiosityProblem problem;
  const int n = mesh.elementCount();
  problem.emission.resize(n);
  problem.reflectance.resize(n);
  problem.area.resize(n);
  std::vector<CoverageMap> coverage;
  for (const Material& m : scene.materials) coverage.emplace_back(m, scene.textures);
  for (int e = 0; e < n; ++e) {
    const Material& m = scene.materials[mesh.material(e)];
    // Lambertian emitter: exitance = pi × radiance. Textures enter as their area average over
    // the element, so the element reflects and emits what its surface does in total.
    problem.emission[e] = M_PI * elementEmission(scene, mesh, e);
    // Mirrors and glass hold no radiosity: rays pass on through them (extended form factors).
    problem.reflectance[e] = m.isSpecular() ? Rgb() : elementReflectance(scene, mesh, e);
    // A cut-out element keeps its area; only its covered fraction (rays pass the rest, see
    // RayCaster) emits and reflects, so both scale by its average coverage.
    const CoverageMap& mask = coverage[static_cast<std::size_t>(mesh.material(e))];
    if (mask.hasHoles() && mesh.hasUvs(e)) {
      const double covered = mask.average(mesh.cornerUvs(e));
      problem.emission[e] = covered * problem.emission[e];
      problem.reflectance[e] = covered * problem.reflectance[e];
    }
    // Power per unit area is over the part light can reach: a buried part neither receives nor
    // shoots (the rows drop rays that leave it).
    problem.area[e] = mesh.area(e) * (exposure ? exposure->exposedFraction(e) : 1.0);
  }
  return problem;
}

std::vector<SpecularSurface> specularSurfaces(const Scene& scene, const PatchMesh& mesh) {
  std::vector<SpecularSurface> surfaces(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Material& m = scene.materials[mesh.material(e)];
    if (m.kind == SurfaceKind::Mirror)
      surfaces[e] = {SpecularSurface::Kind::Mirror, m.specular, Rgb::all(1), 1};
    if (m.kind == SurfaceKind::Dielectric)
      surfaces[e] = {SpecularSurface::Kind::Dielectric, Rgb::all(1), m.transmittance, m.ior};
  }
  return surfaces;
}

// A shooter's row decides how evenly its power lands on the receivers. An emitter element shoots
// a large share of all the light (all of it, at first), so its row gets rays in proportion to
// that share: with n elements, an element emitting the fraction s of a source's power gets about
// s·n times the rays of an average element (at least 1×, at most 64×); with several sources, its
// largest share of any one. A uniform emitter gets 1×.
std::vector<int> sourceRayMultipliers(const std::vector<double>& area,
                                      const std::vector<std::vector<Rgb>>& sourcePower) {
  const size_t n = area.size();
  std::vector<int> multiplier(n, 1);
  for (const std::vector<Rgb>& source : sourcePower) {
    double total = 0;
    for (size_t i = 0; i < n; ++i) total += area[i] * source[i].sum();
    if (!(total > 0)) continue;
    for (size_t i = 0; i < n; ++i) {
      const double share = area[i] * source[i].sum() / total;
      multiplier[i] =
          std::max(multiplier[i], static_cast<int>(std::clamp(std::round(share * n), 1.0, 64.0)));
    }
  }
  return multiplier;
}

std::vector<int> emitterRayMultipliers(const RadiosityProblem& problem) {
  return sourceRayMultipliers(problem.area, {problem.emission});
}

ElementExposure solveExposure(const SolveOptions& options, const PatchMesh& mesh,
                              const RayCaster& rays) {
  return options.formFactors == FormFactorMethod::Hemisphere ? ElementExposure(mesh, rays)
                                                             : ElementExposure();
}

}  // namespace rad
