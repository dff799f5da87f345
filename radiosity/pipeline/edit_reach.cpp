#include "radiosity/pipeline/edit_reach.h"

#include <algorithm>
#include <cmath>

namespace rad {
namespace {

// The eight corners of the box.
std::array<Eigen::Vector3d, 8> boxCorners(const EditBox& box) {
  std::array<Eigen::Vector3d, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = Eigen::Vector3d(k & 1 ? box.hi.x() : box.lo.x(), k & 2 ? box.hi.y() : box.lo.y(),
                           k & 4 ? box.hi.z() : box.lo.z());
  return c;
}

// Every point of the box lies behind the element's plane (by more than the margin).
bool behindPlane(const std::array<Eigen::Vector3d, 3>& corners, const Eigen::Vector3d& normal,
                 const EditBox& box, double margin) {
  for (const Eigen::Vector3d& c : boxCorners(box))
    if ((c - corners[0]).dot(normal) > -margin) return false;
  return true;
}

// Every point of the box lies below the element's lowest point along `up`.
bool belowElement(const std::array<Eigen::Vector3d, 3>& corners, const Eigen::Vector3d& up,
                  const EditBox& box, double margin) {
  double lowest = corners[0].dot(up);
  for (const Eigen::Vector3d& p : corners) lowest = std::min(lowest, p.dot(up));
  double highest = -HUGE_VAL;
  for (const Eigen::Vector3d& c : boxCorners(box)) highest = std::max(highest, c.dot(up));
  return highest < lowest - margin;
}

bool segmentsMayMeet(const std::array<Eigen::Vector3d, 3>& corners, const Eigen::Vector3d& lamp,
                     const EditBox& box, double margin) {
  Eigen::Vector3d lo = lamp, hi = lamp;
  for (const Eigen::Vector3d& p : corners) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (lo.array() - margin <= box.hi.array()).all() &&
         (hi.array() + margin >= box.lo.array()).all();
}

// Rays from the element along directions at most atan(spread) off `axis`.
bool beamMayMeet(const std::array<Eigen::Vector3d, 3>& corners, const Eigen::Vector3d& axis,
                 double spread, const EditBox& box, double margin) {
  const Eigen::Vector3d c = (corners[0] + corners[1] + corners[2]) / 3;
  double r = 0;
  for (const Eigen::Vector3d& p : corners) r = std::max(r, (p - c).norm());
  r += margin;
  const Eigen::Vector3d centre = (box.lo + box.hi) / 2;
  const double R = (box.hi - box.lo).norm() / 2 + margin;
  const Eigen::Vector3d v = centre - c;
  const double along = v.dot(axis);
  // Beam points q: along(q) >= -r, and their distance from the axis through c is at most
  // r + (along(q) + r) tan h, tan h = spread (a ray from within r of c, at most h off the axis,
  // has gone at most (along(q) + r) / cos h).
  if (along + R < -r) return false;
  const double lateral = (v - along * axis).norm();
  return lateral - R <= r + (along + R + r) * spread;
}

bool sunBeamMayMeet(const Light& sun, const std::array<Eigen::Vector3d, 3>& corners,
                    const EditBox& box, double margin) {
  const double halfAngle = 0.5 * sun.angularDiameterDegrees * M_PI / 180;
  // The diameter is below 90°: h below 45°.
  return beamMayMeet(corners, -sun.direction.normalized(), std::tan(halfAngle), box, margin);
}

}  // namespace

bool shadowRaysMayMeet(const Light& light, const std::array<Eigen::Vector3d, 3>& corners,
                       const Eigen::Vector3d& normal, const EditBox& box, double margin) {
  switch (light.type) {
    case LightType::Point:
    case LightType::Spot:
      return segmentsMayMeet(corners, light.position, box, margin);
    case LightType::Directional:
      return sunBeamMayMeet(light, corners, box, margin);
    case LightType::Sky:
      return !behindPlane(corners, normal, box, margin) &&
             !belowElement(corners, light.up, box, margin);
    case LightType::Environment:
      return !behindPlane(corners, normal, box, margin);
  }
  return true;
}

bool raysAlongMayMeet(const std::array<Eigen::Vector3d, 3>& corners,
                      const Eigen::Vector3d& direction, const EditBox& box, double margin) {
  return beamMayMeet(corners, direction.normalized(), 0, box, margin);
}

}  // namespace rad
