#include "radiosity/render/render_scene.h"

namespace rad {

RenderScene::RenderScene(const Scene& scene, const PatchMesh& mesh, const RayCaster& caster)
    : scene_(scene), mesh_(mesh), caster_(caster), emitters_(scene, mesh) {
  const int n = mesh.elementCount();
  corners_.resize(n);
  normals_.resize(n);
  for (int e = 0; e < n; ++e) {
    corners_[e] = mesh.corners(e);
    normals_[e] = mesh.normal(e);
    hasSpecular_ = hasSpecular_ || material(e).isSpecular();
  }
}

SurfaceHit RenderScene::intersect(const Eigen::Vector3d& origin,
                                  const Eigen::Vector3d& direction) const {
  const RayHit h = caster_.closestHit(origin, direction);
  SurfaceHit hit;
  if (!h.hit()) return hit;
  hit.element = h.element;
  hit.u = h.u;
  hit.v = h.v;
  // The point from the barycentrics lies on the triangle in double precision, free of the
  // float error of origin + t·direction.
  const auto& c = corners_[h.element];
  hit.position = (1 - h.u - h.v) * c[0] + h.u * c[1] + h.v * c[2];
  hit.distance = (hit.position - origin).norm();
  hit.normal = normals_[h.element];
  hit.front = hit.normal.dot(direction) < 0;
  hit.material = &material(h.element);
  return hit;
}

bool RenderScene::occluded(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  Eigen::Vector3d d = to - from;
  const double length = d.norm();
  if (!(length > 2 * caster_.surfaceOffset())) return false;
  d /= length;
  return caster_.occluded(from, d, length - 2 * caster_.surfaceOffset());
}

}  // namespace rad
