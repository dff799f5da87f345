#include "radiosity/render/camera.h"

#include <Eigen/Geometry>
#include <cmath>

namespace rad {

CameraRays::CameraRays(const Camera& camera) : camera_(camera) {
  forward_ = (camera.lookAt - camera.position).normalized();
  right_ = forward_.cross(camera.up).normalized();
  up_ = right_.cross(forward_);
  tanHalfY_ = std::tan(0.5 * camera.vfovDegrees * M_PI / 180.0);
  tanHalfX_ = tanHalfY_ * camera.width / camera.height;
}

void CameraRays::generate(double px, double py, double lu, double lv, Eigen::Vector3d& origin,
                          Eigen::Vector3d& direction) const {
  const double sx = (2.0 * px / camera_.width - 1.0) * tanHalfX_;
  const double sy = (1.0 - 2.0 * py / camera_.height) * tanHalfY_;
  direction = (forward_ + sx * right_ + sy * up_).normalized();
  origin = camera_.position;
  if (camera_.lensRadius > 0) {
    // Thin lens: every ray through the pixel meets the pinhole ray on the plane of focus.
    const double cosTheta = direction.dot(forward_);
    const Eigen::Vector3d focus = origin + direction * (camera_.focusDistance / cosTheta);
    const double r = camera_.lensRadius * std::sqrt(lu), phi = 2 * M_PI * lv;
    origin += r * std::cos(phi) * right_ + r * std::sin(phi) * up_;
    direction = (focus - origin).normalized();
  }
}

}  // namespace rad
