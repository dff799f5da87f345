#include "radiosity/render/render_scene.h"

#include <limits>

#include "radiosity/scene/surface_textures.h"

namespace rad {

RenderScene::RenderScene(const Scene& scene, const PatchMesh& mesh, const RayCaster& caster,
                         const SceneMotion* motion)
    : scene_(scene),
      mesh_(mesh),
      caster_(caster),
      motion_(motion),
      emitters_(scene, mesh),
      lights_(scene.lights) {
  const int n = mesh.elementCount();
  corners_.resize(n);
  normals_.resize(n);
  for (int e = 0; e < n; ++e) {
    corners_[e] = mesh.corners(e);
    normals_[e] = mesh.normal(e);
    hasSpecular_ = hasSpecular_ || material(e).isSpecular();
  }
}

SurfaceHit RenderScene::intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  double time) const {
  const RayHit h =
      caster_.closestHit(origin, direction, std::numeric_limits<double>::infinity(), time);
  SurfaceHit hit;
  if (!h.hit()) return hit;
  hit.element = h.element;
  hit.u = h.u;
  hit.v = h.v;
  // The point from the barycentrics lies on the triangle in double precision, free of the
  // float error of origin + t·direction.
  const auto& c = corners_[h.element];
  hit.position = (1 - h.u - h.v) * c[0] + h.u * c[1] + h.v * c[2];
  if (motion_) hit.position += motion_->displacement(h.element, time);  // translation only
  hit.distance = (hit.position - origin).norm();
  hit.normal = normals_[h.element];
  hit.front = hit.normal.dot(direction) < 0;
  hit.material = &material(h.element);
  hit.diffuse = reflectanceAt(scene_, mesh_, h.element, h.u, h.v);
  return hit;
}

bool RenderScene::occluded(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                           double time) const {
  Eigen::Vector3d d = to - from;
  const double length = d.norm();
  if (!(length > 2 * caster_.surfaceOffset())) return false;
  d /= length;
  return caster_.occluded(from, d, length - 2 * caster_.surfaceOffset(), time);
}

bool RenderScene::occludedAlong(const Eigen::Vector3d& from, const Eigen::Vector3d& direction,
                                double time) const {
  return caster_.occluded(from, direction, std::numeric_limits<double>::infinity(), time);
}

}  // namespace rad
