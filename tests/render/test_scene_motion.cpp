// The motion-blur fields of the camera sidecar: what they describe, and every way they can be
// wrong, each an InputError naming the file and the line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/scene_motion.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
const std::string kData = std::string(RADIOSITY_DATA_DIR) + "/tests/";

fs::path scratchFile(const std::string& name) {
  return fs::temp_directory_path() / ("radiosity_test_" + std::to_string(::getpid()) + "_" + name);
}

// A camera file with `extra` (starting with a comma) after the camera keys, from line 8 on.
fs::path writeCamera(const std::string& name, const std::string& extra) {
  const fs::path path = scratchFile(name);
  std::ofstream f(path);
  f << "{\n  \"position\": [0, 0, -1],\n  \"look_at\": [0, 0, 1],\n  \"up\": [0, 1, 0],\n"
       "  \"vfov_degrees\": 30,\n  \"width\": 8,\n  \"height\": 8\n"
    << extra << "\n}\n";
  return path;
}

// The message of the InputError `f` throws ("" if none).
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneMotion, ReadsTheShippedSidecar) {
  const std::string camera = kData + "motion_blur.camera.json";
  EXPECT_NO_THROW(loadCamera(camera));  // the camera loader accepts the motion keys
  const MotionSpec spec = loadMotionSpec(camera);
  ASSERT_EQ(spec.objects.size(), 1u);
  EXPECT_EQ(spec.objects[0].name, "mover");
  EXPECT_EQ(spec.objects[0].velocity, Eigen::Vector3d(0.4, 0, 0));
  EXPECT_EQ(spec.shutterOpen, 0);
  EXPECT_EQ(spec.shutterClose, 1);

  const Scene scene = loadObjScene(kData + "motion_blur.obj");
  const PatchMesh mesh = buildPatchMesh(scene);
  const SceneMotion motion(scene, mesh, spec);
  EXPECT_EQ(motion.movingElements(), 2);  // the square's two triangles
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const bool moving = scene.polygons[mesh.patch(e)].object == "mover";
    EXPECT_EQ(motion.displacement(e, 0.5),
              moving ? Eigen::Vector3d(0.2, 0, 0) : Eigen::Vector3d::Zero());
  }
}

// A shutter [2, 4] with velocity v moves the object by 2v..4v: the OBJ holds time 0.
TEST(SceneMotion, ShutterTimesScaleTheDisplacement) {
  const fs::path camera = writeCamera(
      "motion_shutter.json",
      "  ,\"shutter\": [2, 4],\n  \"motion\": [{\"object\": \"mover\", \"velocity\": [1, 0, 0]}]");
  const Scene scene = loadObjScene(kData + "motion_blur.obj");
  const PatchMesh mesh = buildPatchMesh(scene);
  const SceneMotion motion(scene, mesh, loadMotionSpec(camera.string()));
  int movers = 0, still = 0;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (scene.polygons[mesh.patch(e)].object == "mover") {
      EXPECT_EQ(motion.displacement(e, 0), Eigen::Vector3d(2, 0, 0));
      EXPECT_EQ(motion.displacement(e, 1), Eigen::Vector3d(4, 0, 0));
      ++movers;
    } else {
      EXPECT_EQ(motion.displacement(e, 1), Eigen::Vector3d::Zero());
      ++still;
    }
  // Not vacuous: the scene has the named object, and something that stays put.
  EXPECT_GT(movers, 0);
  EXPECT_GT(still, 0);
  fs::remove(camera);
}

struct BadMotion {
  const char* name;
  const char* extra;  // appended to the camera object
  int line;           // where the error must point
  const char* words;  // part of the message
};

class BadMotionFile : public ::testing::TestWithParam<BadMotion> {};

TEST_P(BadMotionFile, NamesFileAndLine) {
  const BadMotion& bad = GetParam();
  const fs::path camera = writeCamera(std::string("motion_bad_") + bad.name + ".json", bad.extra);
  const std::string message = errorOf([&] {
    const MotionSpec spec = loadMotionSpec(camera.string());
    const Scene scene = loadObjScene(kData + "motion_blur.obj");
    const PatchMesh mesh = buildPatchMesh(scene);
    SceneMotion motion(scene, mesh, spec);
  });
  EXPECT_NE(message.find(camera.string() + ":" + std::to_string(bad.line) + ":"), std::string::npos)
      << message;
  EXPECT_NE(message.find(bad.words), std::string::npos) << message;
  fs::remove(camera);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadMotionFile,
    ::testing::Values(
        BadMotion{"shutter_reversed", "  ,\"shutter\": [1, 0]", 8, "open <= close"},
        BadMotion{"shutter_one", "  ,\"shutter\": [1]", 8, "\"shutter\" must be"},
        BadMotion{"motion_object", "  ,\"motion\": {\"object\": \"mover\"}", 8,
                  "\"motion\" must be an array"},
        BadMotion{"no_velocity", "  ,\"motion\": [\n  {\"object\": \"mover\"}]", 9, "velocity"},
        BadMotion{"nan_velocity",
                  "  ,\"motion\": [\n  {\"object\": \"mover\", \"velocity\": [1, \"a\", 0]}]", 9,
                  "3 finite numbers"},
        BadMotion{"unknown_key",
                  "  ,\"motion\": [\n  {\"object\": \"mover\", \"speed\": [1, 0, 0]}]", 9,
                  "unknown key \"speed\""},
        BadMotion{"twice",
                  "  ,\"motion\": [\n  {\"object\": \"mover\", \"velocity\": [1, 0, 0]},\n"
                  "  {\"object\": \"mover\", \"velocity\": [0, 1, 0]}]",
                  10, "already moves"},
        BadMotion{"unknown_object",
                  "  ,\"motion\": [\n  {\"object\": \"mover\", \"velocity\": [1, 0, 0]},\n"
                  "  {\"object\": \"ghost\", \"velocity\": [0, 1, 0]}]",
                  10, "'ghost' is no 'o' or 'g' group"},
        BadMotion{"moving_emitter",
                  "  ,\"motion\": [\n  {\"object\": \"backdrop\", \"velocity\": [1, 0, 0]}]", 9,
                  "emits light"}),
    [](const ::testing::TestParamInfo<BadMotion>& info) { return std::string(info.param.name); });

// Two groups sharing a vertex cannot move apart without tearing the mesh.
TEST(SceneMotion, SharedVerticesAreAnError) {
  const fs::path obj = scratchFile("motion_shared.obj");
  {
    std::ofstream f(obj);
    f << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\no a\nf 1 2 3\no b\nf 2 4 3\n";
  }
  const fs::path camera = writeCamera(
      "motion_shared.json", "  ,\"motion\": [\n  {\"object\": \"a\", \"velocity\": [1, 0, 0]}]");
  const Scene scene = loadObjScene(obj.string());
  const PatchMesh mesh = buildPatchMesh(scene);
  const std::string message =
      errorOf([&] { SceneMotion(scene, mesh, loadMotionSpec(camera.string())); });
  EXPECT_NE(message.find(camera.string() + ":9:"), std::string::npos) << message;
  EXPECT_NE(message.find("shares vertices"), std::string::npos) << message;
  fs::remove(obj);
  fs::remove(camera);
}

}  // namespace
}  // namespace rad
