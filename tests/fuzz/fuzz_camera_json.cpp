// libFuzzer target: the camera JSON sidecar (<scene>.camera.json, --camera FILE) through its one
// reader, loadCamera() (radiosity/scene/camera.h), both directly (render --camera) and as the
// scene's sidecar through findSceneCamera() (render, compare and view --camera-from-scene). A
// camera it accepts must give finite unit primary rays, and both ways must agree.
// Findings: crashes, sanitizer reports, and any exception other than InputError.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/render/camera.h"
#include "radiosity/scene/camera.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_camera_json: %s\n", what);
  std::abort();
}

// The sidecar next to the scene: <dir>/scene.obj -> <dir>/scene.camera.json. Returns whether it
// was accepted.
bool sceneSidecar(const std::string& cameraPath, const std::optional<rad::Camera>& direct) {
  const std::string scenePath = cameraPath.substr(0, cameraPath.size() - 12) + ".obj";
  std::optional<rad::Camera> camera;
  try {
    camera = rad::findSceneCamera(scenePath);
  } catch (const rad::InputError&) {
    check(!direct, "findSceneCamera refused a camera loadCamera accepted");
    return false;
  }
  check(camera.has_value(), "findSceneCamera did not find the sidecar");
  check(direct.has_value(), "findSceneCamera accepted a camera loadCamera refused");
  check(camera->position == direct->position && camera->lookAt == direct->lookAt &&
            camera->up == direct->up && camera->vfovDegrees == direct->vfovDegrees &&
            camera->width == direct->width && camera->height == direct->height,
        "findSceneCamera and loadCamera read different cameras");
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      rad::fuzz::writeTemp("scene.camera.json", reinterpret_cast<const char*>(data), size);
  std::optional<rad::Camera> direct;
  try {
    direct = rad::loadCamera(path);
  } catch (const rad::InputError&) {
  }
  if (!sceneSidecar(path, direct)) return 0;
  const rad::Camera& camera = *direct;
  check(camera.position.allFinite() && camera.lookAt.allFinite() && camera.up.allFinite() &&
            camera.vfovDegrees > 0 && camera.vfovDegrees < 180,
        "an accepted camera is not finite or has no field of view");
  rad::CameraRays rays(camera);
  for (double p : {0.0, 0.5, 0.999}) {
    Eigen::Vector3d origin, direction;
    rays.generate(p * camera.width, p * camera.height, p, 1 - p, origin, direction);
    check(origin.allFinite() && direction.allFinite() && std::abs(direction.norm() - 1) <= 1e-6,
          "an accepted camera gives a bad primary ray");
  }
  return 0;
}
