#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "radiosity/scene/camera.h"

namespace rad {

// Primary rays: an orthonormal frame built once, then one ray per (pixel, sample) position.
class CameraRays {
 public:
  explicit CameraRays(const Camera& camera);
  // (px, py): continuous pixel coordinates (x right, y down, pixel (0,0) covers [0,1)²);
  // (lu, lv) in [0,1)² pick the point on the lens (ignored for a pinhole).
  void generate(double px, double py, double lu, double lv, Eigen::Vector3d& origin,
                Eigen::Vector3d& direction) const;
  const Eigen::Vector3d& forward() const { return forward_; }
  const Eigen::Vector3d& right() const { return right_; }
  const Eigen::Vector3d& up() const { return up_; }

 private:
  Camera camera_;
  Eigen::Vector3d forward_, right_, up_;
  double tanHalfY_ = 0, tanHalfX_ = 0;
};

}  // namespace rad
