#include "radiosity/render/texel_radiance.h"

#include "radiosity/scene/surface_textures.h"

namespace rad {

Rgb TexelRadiance::outgoingRadiance(int element, const TexelFootprint& footprint, Rng& rng,
                                    RayCounts& counts, Rgb& standardError) const {
  RandomSampler sampler(rng);
  return outgoingRadiance(element, footprint, sampler, counts, standardError);
}

Rgb TexelRadiance::outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                                    RayCounts& counts, Rgb& standardError) const {
  TexelFootprint point;
  point.centre = barycentric;
  return outgoingRadiance(element, point, rng, counts, standardError);
}

Rgb TexelRadiance::outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                                    RayCounts& counts) const {
  Rgb unused;
  return outgoingRadiance(element, barycentric, rng, counts, unused);
}

SurfaceHit texelHit(const RenderScene& scene, int element, const Eigen::Vector3d& barycentric) {
  const PatchMesh& mesh = scene.mesh();
  const auto c = mesh.corners(element);
  SurfaceHit hit;
  hit.element = element;
  hit.position = barycentric[0] * c[0] + barycentric[1] * c[1] + barycentric[2] * c[2];
  hit.u = barycentric[1];
  hit.v = barycentric[2];
  hit.diffuse = reflectanceAt(scene.scene(), mesh, element, hit.u, hit.v);
  hit.normal = mesh.normal(element);
  hit.front = true;
  hit.material = &scene.material(element);
  return hit;
}

}  // namespace rad
