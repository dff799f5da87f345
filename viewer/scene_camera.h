#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

namespace rad {

struct CameraSpec {
  Eigen::Vector3d position{0, 0, 0}, lookAt{0, 0, 1}, up{0, 1, 0};
  double vfovDegrees = 30;
};

// `<dir>/<stem>.camera.json` for a scene `<dir>/<stem>.obj`.
std::string viewCameraFile(const std::string& scenePath);

// The camera of the scene's sidecar, if there is one: keys "position", "look_at", "up" (three
// numbers each) and "vfov_degrees"; other keys are ignored. InputError naming the file for
// malformed JSON, missing keys or a degenerate camera.
std::optional<CameraSpec> readCameraSidecar(const std::string& scenePath);

// A camera that frames the box [min, max]: it looks along `direction` (need not be unit) at the
// box's centre from far enough that the bounding sphere fits the field of view at `aspect`
// (width / height). Up is +y, or +z when looking along y.
CameraSpec frameBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                       const Eigen::Vector3d& direction, double aspect, double vfovDegrees = 30);

}  // namespace rad
