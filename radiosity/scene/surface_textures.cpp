#include "radiosity/scene/surface_textures.h"

#include <algorithm>

namespace rad {
namespace {

// The texture that multiplies the factor on this element, or null.
const Texture* textureOn(const Scene& scene, const PatchMesh& mesh, int element, int texture) {
  if (texture < 0 || !mesh.hasUvs(element)) return nullptr;
  return &scene.textures[texture];
}

Eigen::Vector2d uvAt(const PatchMesh& mesh, int element, double u, double v) {
  const std::array<Eigen::Vector2d, 3> uv = mesh.cornerUvs(element);
  return (1 - u - v) * uv[0] + u * uv[1] + v * uv[2];
}

Rgb clampReflectance(const Rgb& rho) {
  return {std::clamp(rho.r, 0.0, 1.0), std::clamp(rho.g, 0.0, 1.0), std::clamp(rho.b, 0.0, 1.0)};
}

}  // namespace

Rgb elementReflectance(const Scene& scene, const PatchMesh& mesh, int element) {
  const Material& m = scene.materials[mesh.material(element)];
  const Texture* t = textureOn(scene, mesh, element, m.diffuseTexture);
  return t ? clampReflectance(m.diffuse * t->averageColour(mesh.cornerUvs(element))) : m.diffuse;
}

Rgb elementEmission(const Scene& scene, const PatchMesh& mesh, int element) {
  const Material& m = scene.materials[mesh.material(element)];
  const Texture* t = textureOn(scene, mesh, element, m.emissionTexture);
  return t ? m.emission * t->averageColour(mesh.cornerUvs(element)) : m.emission;
}

Rgb reflectanceAt(const Scene& scene, const PatchMesh& mesh, int element, double u, double v) {
  const Material& m = scene.materials[mesh.material(element)];
  const Texture* t = textureOn(scene, mesh, element, m.diffuseTexture);
  return t ? clampReflectance(m.diffuse * t->colour(uvAt(mesh, element, u, v))) : m.diffuse;
}

Rgb emissionAt(const Scene& scene, const PatchMesh& mesh, int element, double u, double v) {
  const Material& m = scene.materials[mesh.material(element)];
  const Texture* t = textureOn(scene, mesh, element, m.emissionTexture);
  return t ? m.emission * t->colour(uvAt(mesh, element, u, v)) : m.emission;
}

Rgb incidentLight(const Rgb& outgoing, const Rgb& emitted, const Rgb& rho) {
  Rgb out;
  // B ≥ E for a converged solution; a solver stopped early never goes below E either.
  for (int c = 0; c < 3; ++c)
    if (rho[c] > 0) out[c] = std::max(0.0, outgoing[c] - emitted[c]) / rho[c];
  return out;
}

bool hasReflectanceTexture(const Scene& scene, const PatchMesh& mesh, int element) {
  return textureOn(scene, mesh, element, scene.materials[mesh.material(element)].diffuseTexture);
}

}  // namespace rad
