// libFuzzer target: the lights file (<scene>.lights.json, --lights FILE) through its one reader,
// loadLights() (radiosity/scene/lights.h), both directly and as the scene's sidecar through
// findSceneLights(). Every error must name the file; lights it accepts must have finite, valid
// values (unit directions, non-negative colours, cones and angles in range), and both ways must
// agree. Findings: crashes, sanitizer reports, and any exception other than InputError. A small
// Radiance HDR image, sky.hdr, lies beside the file, so an environment light naming it is read.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/scene/lights.h"
#include "tests/fuzz/fuzz_temp_dir.h"
#include "tests/support/hdr_writer.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_lights_json: %s\n", what);
  std::abort();
}

bool unit(const Eigen::Vector3d& v) { return v.allFinite() && std::abs(v.norm() - 1) <= 1e-9; }

bool valid(const rad::Rgb& c) { return c.isFinite() && c.minComponent() >= 0; }

void checkLight(const rad::Light& l) {
  check(l.position.allFinite() && unit(l.direction) && unit(l.up), "bad position or direction");
  check(valid(l.intensity) && valid(l.irradiance) && valid(l.radiance), "bad colour");
  check(
      l.cosOuter >= -1e-12 && l.cosOuter < 1 && l.cosInner >= l.cosOuter && l.cosInner < 1 + 1e-12,
      "bad spot cones");
  check(l.angularDiameterDegrees >= 0 && l.angularDiameterDegrees < 90, "bad angular diameter");
  check(l.type == rad::LightType::Sky || l.skyModel == rad::SkyModel::Uniform,
        "a sky model on a light that is no sky");
  // The environment and the clear sky carry their map (the image, the sampling table); no other.
  const bool mapped = l.type == rad::LightType::Environment ||
                      (l.type == rad::LightType::Sky && l.skyModel == rad::SkyModel::CieClear);
  check(mapped == (l.map != nullptr), "a map missing, or on a light that takes none");
  if (l.map) {
    check(l.map->width() > 0 && l.map->height() > 0 && unit(l.map->up()), "bad map");
    for (const rad::Rgb& t : l.map->texels()) check(valid(t), "bad map texel");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool image = [] {
    rad::testing::writeHdr((rad::fuzz::tempDir() / "sky.hdr").string(), 4, 2,
                           {{1, 2, 3},
                            {4, 4, 4},
                            {0, 0, 0},
                            {8, 1, 1},
                            {0.5, 0.5, 0.5},
                            {0.5, 0.5, 0.5},
                            {0, 0, 0},
                            {0.25, 0.25, 0.25}});
    return true;
  }();
  (void)image;
  const std::string path =
      rad::fuzz::writeTemp("scene.lights.json", reinterpret_cast<const char*>(data), size);
  std::optional<std::vector<rad::Light>> direct;
  try {
    direct = rad::loadLights(path);
  } catch (const rad::InputError& e) {
    check(std::string(e.what()).find(path) != std::string::npos, "an error does not name the file");
  }
  const std::string scenePath = path.substr(0, path.size() - 12) + ".obj";
  std::optional<std::vector<rad::Light>> sidecar;
  try {
    sidecar = rad::findSceneLights(scenePath, {}, /*log=*/false);
  } catch (const rad::InputError&) {
  }
  check(direct.has_value() == sidecar.has_value(), "findSceneLights and loadLights disagree");
  if (!direct) return 0;
  check(direct->size() == sidecar->size(), "findSceneLights and loadLights read different lights");
  for (const rad::Light& light : *direct) checkLight(light);
  return 0;
}
