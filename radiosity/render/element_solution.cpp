#include "radiosity/render/element_solution.h"

#include <algorithm>

#include "radiosity/scene/surface_textures.h"

namespace rad {

ElementSolution::ElementSolution(const RenderScene& scene, const std::vector<Rgb>& radiosity) {
  const int n = scene.mesh().elementCount();
  radiance.resize(n);
  reflected.resize(n);
  emitted.resize(n);
  rho.resize(n);
  for (int e = 0; e < n; ++e) {
    const Rgb b = radiosity.at(e);
    emitted[e] = elementEmission(scene.scene(), scene.mesh(), e);
    rho[e] = elementReflectance(scene.scene(), scene.mesh(), e);
    radiance[e] = b / M_PI;
    // B ≥ E holds exactly for a converged solution; a solver stopped early never goes below E.
    reflected[e] = (b - M_PI * emitted[e]) / M_PI;
    for (int c = 0; c < 3; ++c) reflected[e][c] = std::max(0.0, reflected[e][c]);
  }
}

std::vector<double> exposedAreas(const PatchMesh& mesh, const ElementExposure& exposure) {
  std::vector<double> areas(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    areas[e] = mesh.area(e) * exposure.exposedFraction(e);
  return areas;
}

std::vector<Eigen::Vector3d> asVectors(const std::vector<Rgb>& perElement) {
  std::vector<Eigen::Vector3d> out(perElement.size());
  for (size_t e = 0; e < perElement.size(); ++e)
    out[e] = {perElement[e].r, perElement[e].g, perElement[e].b};
  return out;
}

}  // namespace rad
