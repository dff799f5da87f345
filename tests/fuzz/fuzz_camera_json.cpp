// libFuzzer target: the camera JSON sidecar (<scene>.camera.json, --camera FILE) through
// loadCamera() and its validation. A camera it accepts must give finite unit primary rays.
// Findings: crashes, sanitizer reports, and any exception other than InputError.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "radiosity/core/errors.h"
#include "radiosity/render/camera.h"
#include "tests/fuzz/fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      rad::fuzz::writeTemp("scene.camera.json", reinterpret_cast<const char*>(data), size);
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
    if (!origin.allFinite() || !direction.allFinite() || std::abs(direction.norm() - 1) > 1e-6) {
      std::fprintf(stderr, "fuzz_camera_json: an accepted camera gives a bad primary ray\n");
      std::abort();
    }
  }
  return 0;
}
