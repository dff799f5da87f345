// libFuzzer target: OBJ + MTL through the project's own loading and validation (loadScene's
// format recognition, then line checks, tinyobjloader, material and index checks), then the
// solver's scene limits and the meshing a solve would do. One input holds both files: the OBJ, then
// optionally a line "#%MTL%" and the MTL, written as scene.mtl next to scene.obj (so `mtllib
// scene.mtl` finds it).
//
// Findings: crashes, sanitizer reports, and any exception other than InputError (a
// RuntimeFailure here means tinyobjloader and the line check disagreed on a file: a bug).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "meshing/mesh_uv_layout.h"
#include "meshing/patch_mesh.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace {

constexpr const char kSeparator[] = "\n#%MTL%\n";

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_obj_scene: invariant violated: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool quiet = (rad::setLogLevel(rad::LogLevel::Quiet), true);
  (void)quiet;
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find(kSeparator);
  const std::string obj = input.substr(0, split);
  const std::string mtl =
      split == std::string::npos ? std::string() : input.substr(split + std::strlen(kSeparator));
  const std::string objPath = rad::fuzz::writeTemp("scene.obj", obj.data(), obj.size());
  rad::fuzz::writeTemp("scene.mtl", mtl.data(), mtl.size());

  rad::Scene scene;
  try {
    scene = rad::loadScene(objPath);
    rad::checkSceneLimits(scene);
  } catch (const rad::InputError& e) {
    check(std::strlen(e.what()) > 0, "an InputError without a message");
    return 0;  // rejected with a message: the expected outcome for bad input
  }
  // What the loader promises the rest of the pipeline.
  for (const rad::ScenePolygon& polygon : scene.polygons) {
    check(polygon.vertices.size() >= 3, "a polygon with fewer than 3 vertices");
    check(polygon.material >= 0 && polygon.material < static_cast<int>(scene.materials.size()),
          "a polygon with a material out of range");
    for (int v : polygon.vertices)
      check(v >= 0 && v < static_cast<int>(scene.positions.size()), "a vertex index out of range");
    check(polygon.uvs.empty() || polygon.uvs.size() == polygon.vertices.size(),
          "texture coordinates not one per corner");
    for (const Eigen::Vector2d& uv : polygon.uvs) check(uv.allFinite(), "a non-finite UV");
  }
  for (const rad::Material& m : scene.materials)
    check(m.diffuse.isFinite() && m.emission.isFinite() && m.diffuse.maxComponent() <= 1 &&
              m.diffuse.minComponent() >= 0 && m.emission.minComponent() >= 0,
          "a material outside its documented range");
  if (scene.polygons.empty()) return 0;
  // The scene's UVs as lightmap UVs (bake --use-scene-uvs): refused with a message, or usable.
  bool uvsUsable = true;
  try {
    rad::checkLightmapUvs(scene);
  } catch (const rad::InputError& e) {
    check(std::strlen(e.what()) > 0, "an InputError without a message");
    uvsUsable = false;
  }

  // Meshing as a solve does it, with a bounded element count.
  rad::PatchMesh mesh = rad::buildPatchMesh(scene);
  const double area = mesh.totalArea();
  // Known (meshing): a self-intersecting polygon can triangulate to nothing; the solve refuses
  // such a scene with an InputError (solveScene), so it is not a finding here.
  if (!(area > 0) || !std::isfinite(area)) return 0;
  mesh.subdivideUniform(area / 32);
  double sum = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) sum += mesh.area(e);
  check(std::abs(sum - area) <= 1e-6 * area, "subdivision changed the total area");
  if (mesh.hasUvs())
    for (int e = 0; e < mesh.elementCount(); ++e)
      for (const Eigen::Vector2d& uv : mesh.cornerUvs(e))
        check(uv.allFinite(), "refinement made a non-finite UV");
  if (uvsUsable) {
    const rad::LightmapLayout layout = rad::layoutFromMeshUvs(mesh, 64, 64, 2);
    check(static_cast<int>(layout.chartOfElement.size()) == mesh.elementCount(),
          "a UV layout without a chart per element");
  }
  return 0;
}
