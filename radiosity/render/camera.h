#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace rad {

// A pinhole or thin-lens camera. Image row 0 is the top; image right is forward × up, so a
// camera looking along +z with up +y sees +x on the LEFT (as in pbrt's LookAt and Blender).
struct Camera {
  Eigen::Vector3d position{0, 0, 0};
  Eigen::Vector3d lookAt{0, 0, 1};
  Eigen::Vector3d up{0, 1, 0};
  double vfovDegrees = 39.3;
  int width = 256, height = 256;
  double lensRadius = 0;     // 0: pinhole
  double focusDistance = 0;  // distance to the plane in focus (used when lensRadius > 0)
};

// Throws InputError when the camera cannot work (zero-length view, up parallel to the view,
// fov outside (0, 180), non-positive size, negative lens radius, missing focus distance).
void validateCamera(const Camera& camera, const std::string& source);

// `<scene without .obj>.camera.json`: the camera that ships next to a scene.
std::string cameraSidecarPath(const std::string& scenePath);

// Reads a camera JSON file: {"position": [x,y,z], "look_at": [x,y,z], "up": [x,y,z],
// "vfov_degrees": f, "width": w, "height": h, "lens_radius": r?, "focus_distance": d?}; the keys
// "shutter" and "motion" (motion blur) are allowed and read by loadMotionSpec (scene_motion.h).
// Throws InputError naming the file (and line, for syntax errors) on bad content.
Camera loadCamera(const std::string& path);

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
