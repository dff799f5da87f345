// libFuzzer target: glTF 2.0 through loadScene (format recognition, the JSON checks, tinygltf,
// the bounds-checked accessors, materials, textures, lights) and loadGltfCamera. An input that
// starts with the binary magic "glTF" is written as scene.glb; any other as scene.gltf, and
// what follows a line "#%BIN%" in it as scene.bin beside it (so `"uri": "scene.bin"` finds it).
//
// Findings: crashes, sanitizer reports, and any exception other than InputError.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/gltf_loader.h"
#include "radiosity/scene/scene_loader.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

constexpr const char kSeparator[] = "\n#%BIN%\n";

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_gltf_scene: invariant violated: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool quiet = (rad::setLogLevel(rad::LogLevel::Quiet), true);
  (void)quiet;
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string path;
  if (input.compare(0, 4, "glTF") == 0) {
    path = rad::fuzz::writeTemp("scene.glb", input.data(), input.size());
  } else {
    const std::size_t split = input.find(kSeparator);
    const std::string json = input.substr(0, split);
    const std::string bin =
        split == std::string::npos ? std::string() : input.substr(split + std::strlen(kSeparator));
    path = rad::fuzz::writeTemp("scene.gltf", json.data(), json.size());
    rad::fuzz::writeTemp("scene.bin", bin.data(), bin.size());
  }

  rad::Scene scene;
  try {
    scene = rad::loadScene(path);
    rad::loadGltfCamera(path);
  } catch (const rad::InputError& e) {
    check(std::strlen(e.what()) > 0, "an InputError without a message");
    return 0;  // rejected with a message: the expected outcome for bad input
  }
  // What the loader promises the rest of the pipeline.
  for (const rad::ScenePolygon& polygon : scene.polygons) {
    check(polygon.vertices.size() == 3, "a glTF polygon that is not a triangle");
    check(polygon.material >= 0 && polygon.material < static_cast<int>(scene.materials.size()),
          "a polygon with a material out of range");
    for (int v : polygon.vertices) {
      check(v >= 0 && v < static_cast<int>(scene.positions.size()), "a vertex index out of range");
      check(scene.positions[v].allFinite(), "a non-finite position");
    }
    check(polygon.uvs.empty() || polygon.uvs.size() == 3, "texture coordinates not one per corner");
    check(polygon.lightmapUvs.empty() || polygon.lightmapUvs.size() == 3,
          "lightmap coordinates not one per corner");
    for (const Eigen::Vector2d& uv : polygon.uvs) check(uv.allFinite(), "a non-finite UV");
  }
  for (const rad::Material& m : scene.materials) {
    check(m.diffuse.isFinite() && m.emission.isFinite() && m.diffuse.maxComponent() <= 1 &&
              m.diffuse.minComponent() >= 0 && m.emission.minComponent() >= 0,
          "a material outside its documented range");
    check(m.diffuseTexture < static_cast<int>(scene.textures.size()) &&
              m.emissionTexture < static_cast<int>(scene.textures.size()),
          "a texture index out of range");
  }
  for (const rad::Light& light : scene.lights)
    check(light.intensity.isFinite() && light.irradiance.isFinite() &&
              light.direction.allFinite() && std::abs(light.direction.norm() - 1) < 1e-9,
          "a light with non-finite values or a direction that is not unit length");
  return 0;
}
