#pragma once

#include <Eigen/Core>
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

// `<scene without its extension>.camera.json`: the camera that ships next to a scene.
std::string cameraSidecarPath(const std::string& scenePath);

// Reads a camera JSON file: {"position": [x,y,z], "look_at": [x,y,z], "up": [x,y,z],
// "vfov_degrees": f, "width": w, "height": h, "lens_radius": r?, "focus_distance": d?,
// "comment": any?}; the keys "shutter" and "motion" (motion blur) are allowed and read by
// loadMotionSpec (render/scene_motion.h). Any other key is an error. Throws InputError naming the
// file (and line, for syntax errors and unknown keys) on bad content. The one reader of camera
// files: render, compare and the viewer all use it.
Camera loadCamera(const std::string& path);

// The camera of the sidecar next to the scene (cameraSidecarPath) when that file exists, read by
// loadCamera (so a sidecar that exists but is bad is an InputError); nullopt when there is none.
std::optional<Camera> findSceneCamera(const std::string& scenePath);

}  // namespace rad
