// libFuzzer target: the camera JSON sidecar (<scene>.camera.json, --camera FILE) through both of
// its readers: loadCamera() (render) and, where the viewer is built, readCameraSidecar() (view
// --camera-from-scene). A camera loadCamera accepts must give finite unit primary rays; one the
// viewer accepts must be finite with a field of view in (0, 180) degrees.
// Findings: crashes, sanitizer reports, and any exception other than InputError.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/render/camera.h"
#include "tests/fuzz/fuzz_temp_dir.h"
#ifdef RADIOSITY_FUZZ_VIEWER
#include "viewer/scene_camera.h"
#endif

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_camera_json: %s\n", what);
  std::abort();
}

#ifdef RADIOSITY_FUZZ_VIEWER
// The viewer finds the sidecar next to the scene: <dir>/scene.obj -> <dir>/scene.camera.json.
void viewerSidecar(const std::string& cameraPath) {
  const std::string scenePath = cameraPath.substr(0, cameraPath.size() - 12) + ".obj";
  std::optional<rad::CameraSpec> camera;
  try {
    camera = rad::readCameraSidecar(scenePath);
  } catch (const rad::InputError&) {
    return;
  }
  check(camera.has_value(), "the viewer did not find the sidecar");
  check(camera->position.allFinite() && camera->lookAt.allFinite() && camera->up.allFinite() &&
            camera->vfovDegrees > 0 && camera->vfovDegrees < 180,
        "the viewer accepted a camera that is not finite or has no field of view");
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      rad::fuzz::writeTemp("scene.camera.json", reinterpret_cast<const char*>(data), size);
#ifdef RADIOSITY_FUZZ_VIEWER
  viewerSidecar(path);
#endif
  rad::Camera camera;
  try {
    camera = rad::loadCamera(path);
  } catch (const rad::InputError&) {
    return 0;
  }
  rad::CameraRays rays(camera);
  for (double p : {0.0, 0.5, 0.999}) {
    Eigen::Vector3d origin, direction;
    rays.generate(p * camera.width, p * camera.height, p, 1 - p, origin, direction);
    check(origin.allFinite() && direction.allFinite() && std::abs(direction.norm() - 1) <= 1e-6,
          "an accepted camera gives a bad primary ray");
  }
  return 0;
}
