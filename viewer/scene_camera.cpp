#include "viewer/scene_camera.h"

#include <vtkCamera.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace rad {

Camera frameBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                   const Eigen::Vector3d& direction, double aspect, double vfovDegrees) {
  Camera c;
  c.vfovDegrees = vfovDegrees;
  const Eigen::Vector3d d = direction.normalized();
  const Eigen::Vector3d centre = 0.5 * (min + max);
  const double radius = std::max(0.5 * (max - min).norm(), 1e-12);
  // The sphere must fit the narrower of the two fields of view.
  const double half = 0.5 * vfovDegrees * M_PI / 180;
  const double halfNarrow = aspect < 1 ? std::atan(std::tan(half) * aspect) : half;
  const double distance = radius / std::sin(halfNarrow);
  c.lookAt = centre;
  c.position = centre - distance * d;
  c.up = std::abs(d.y()) > 0.9 ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(0, 1, 0);
  return c;
}

void applyToView(const Camera& c, vtkCamera& view) {
  view.SetPosition(c.position.data());
  view.SetFocalPoint(c.lookAt.data());
  view.SetViewUp(c.up.data());
  view.SetViewAngle(c.vfovDegrees);
  view.OrthogonalizeViewUp();
}

}  // namespace rad
