#include "radiosity/app/options/camera_options.h"

#include <filesystem>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

Eigen::Vector3d toVector(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

}  // namespace

void addCameraOptions(CLI::App& command, CameraOptions& o, CameraOverrides which) {
  command.add_option("--camera", o.file, "Camera JSON file (default: <scene>.camera.json)");
  if (which == CameraOverrides::All) {
    command.add_option("--position", o.position, "Camera position x y z")->expected(3);
    command.add_option("--look-at", o.lookAt, "Point the camera looks at, x y z")->expected(3);
    command.add_option("--up", o.up, "Camera up vector x y z")->expected(3);
    command.add_option("--vfov", o.vfov, "Vertical field of view, degrees");
    o.placeable = true;
  }
  command.add_option("--width", o.width, "Image width in pixels");
  command.add_option("--height", o.height, "Image height in pixels");
  if (which == CameraOverrides::All) {
    command.add_option("--lens-radius", o.lensRadius, "Thin-lens aperture radius (0: pinhole)");
    command.add_option("--focus-distance", o.focusDistance, "Distance to the plane in focus");
  }
}

ResolvedCamera resolveCamera(const CameraOptions& o, const std::string& scenePath) {
  ResolvedCamera resolved;
  Camera& camera = resolved.camera;
  std::string& source = resolved.file;
  source = o.file;
  if (source.empty()) {
    const std::string sidecar = cameraSidecarPath(scenePath);
    if (std::filesystem::exists(sidecar)) source = sidecar;
  }
  std::optional<Camera> sceneCamera;  // a glTF scene's own camera, when there is no sidecar
  if (source.empty()) sceneCamera = findSceneCamera(scenePath);
  if (!source.empty()) {
    camera = loadCamera(source);
  } else if (sceneCamera) {
    camera = *sceneCamera;
  } else if (o.position.empty() || o.lookAt.empty()) {
    throw InputError(scenePath, 0,
                     "no camera: write " + cameraSidecarPath(scenePath) + " or pass --camera FILE" +
                         (o.placeable ? ", or --position and --look-at" : ""));
  }
  if (!o.position.empty()) camera.position = toVector(o.position);
  if (!o.lookAt.empty()) camera.lookAt = toVector(o.lookAt);
  if (!o.up.empty()) camera.up = toVector(o.up);
  if (o.vfov) camera.vfovDegrees = *o.vfov;
  if (o.width) camera.width = *o.width;
  if (o.height) camera.height = *o.height;
  if (o.lensRadius) camera.lensRadius = *o.lensRadius;
  if (o.focusDistance) camera.focusDistance = *o.focusDistance;
  if (o.focusDistance && !(camera.lensRadius > 0))
    throw InputError(
        "--focus-distance is not used: the camera is a pinhole (lens radius 0); a thin lens "
        "needs --lens-radius");
  const std::string file = !source.empty() ? source : sceneCamera ? scenePath : "";
  validateCamera(camera,
                 file.empty() ? "command line camera" : file + " (with command-line overrides)");
  return resolved;
}

}  // namespace rad
