// Camera conventions: pixel (0,0) top-left, image right = forward × up, sidecar files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/render/camera.h"
#include "radiosity/scene/camera.h"

namespace rad {
namespace {

TEST(Camera, CornellCameraLooksIntoTheBoxWithRedWallOnTheLeft) {
  const Camera c =
      loadCamera(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.camera.json");
  EXPECT_EQ(c.width, 256);
  EXPECT_EQ(c.height, 256);
  // Published: focal length 35 mm on a 25 mm film.
  EXPECT_NEAR(c.vfovDegrees, 2 * std::atan(12.5 / 35) * 180 / M_PI, 1e-4);
  const CameraRays rays(c);
  Eigen::Vector3d o, d;
  rays.generate(0.5, 128, 0, 0, o, d);  // left edge, middle row
  EXPECT_GT(d.x(), 0);                  // looks towards +x: the red wall (x ≈ 0.55)
  rays.generate(128, 0.5, 0, 0, o, d);  // top edge
  EXPECT_GT(d.y(), 0);
  rays.generate(128, 128, 0, 0, o, d);  // centre
  EXPECT_NEAR(d.z(), 1.0, 1e-12);
  // The top edge's ray leaves at half the vertical field of view.
  rays.generate(128, 0, 0, 0, o, d);
  EXPECT_NEAR(std::atan2(d.y(), d.z()) * 180 / M_PI, c.vfovDegrees / 2, 1e-9);
}

TEST(Camera, ThinLensRaysMeetOnThePlaneOfFocus) {
  Camera c;
  c.lensRadius = 0.1;
  c.focusDistance = 2.0;
  const CameraRays rays(c);
  Eigen::Vector3d o0, d0, o1, d1;
  rays.generate(40, 70, 0.0, 0.0, o0, d0);
  rays.generate(40, 70, 0.9, 0.3, o1, d1);
  const Eigen::Vector3d p0 = o0 + d0 * ((2.0 - o0.z()) / d0.z());
  const Eigen::Vector3d p1 = o1 + d1 * ((2.0 - o1.z()) / d1.z());
  EXPECT_LT((p0 - p1).norm(), 1e-12);
  EXPECT_GT((o0 - o1).norm(), 0.01);
}

TEST(Camera, SidecarPathReplacesTheObjExtension) {
  EXPECT_EQ(cameraSidecarPath("data/cornell_box/cornell_box.obj"),
            "data/cornell_box/cornell_box.camera.json");
  EXPECT_EQ(cameraSidecarPath("a.b/scene"), "a.b/scene.camera.json");
}

TEST(Camera, BadFilesNameTheFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / "radiosity_bad_camera.json";
  {
    std::ofstream out(path);
    out << "{\n  \"position\": [0, 0, 0],\n  \"look_at\": [0, 0 1]\n}\n";
  }
  try {
    loadCamera(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":3:"), std::string::npos) << e.what();
  }
  {
    std::ofstream out(path);
    out << R"({"position": [0,0,0], "look_at": [0,0,0], "up": [0,1,0], "vfov_degrees": 40, "width": 8, "height": 8})";
  }
  EXPECT_THROW(loadCamera(path.string()), InputError);
  {
    std::ofstream out(path);
    out << R"({"position": [0,0,0], "look_at": [0,0,1], "up": [0,1,0], "vfov_degrees": 40, "width": 8})";
  }
  EXPECT_THROW(loadCamera(path.string()), InputError);
  std::filesystem::remove(path);
}

// One reader for render, compare and view: an unknown key is an error naming the key, the file
// and the key's line (the viewer used to ignore such keys).
TEST(Camera, UnknownKeysAreErrorsNamingTheKeyFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / "radiosity_unknown_key.camera.json";
  std::ofstream(path) << "{\"position\": [0,0,0], \"look_at\": [0,0,1], \"up\": [0,1,0],\n"
                         "\"vfov_degrees\": 40, \"width\": 8, \"height\": 8,\n"
                         "\"fov\": 40}\n";
  try {
    loadCamera(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path.string() + ":3:"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown camera key \"fov\""), std::string::npos) << what;
  }
  // The motion-blur keys (read by loadMotionSpec) and a comment are allowed.
  std::ofstream(path) << R"({"position": [0,0,0], "look_at": [0,0,1], "up": [0,1,0],
    "vfov_degrees": 40, "width": 8, "height": 8, "comment": "c", "shutter": [0, 1], "motion": []})";
  EXPECT_NO_THROW(loadCamera(path.string()));
  std::filesystem::remove(path);
}

TEST(Camera, FindSceneCameraReadsTheSidecarWhenItExists) {
  const auto dir = std::filesystem::temp_directory_path() / "radiosity_find_scene_camera";
  std::filesystem::create_directories(dir);
  const std::string scene = (dir / "room.obj").string();
  std::filesystem::remove(dir / "room.camera.json");
  EXPECT_FALSE(findSceneCamera(scene).has_value());
  std::ofstream(dir / "room.camera.json") << R"({"position": [1,2,3], "look_at": [1,2,4],
    "up": [0,1,0], "vfov_degrees": 50, "width": 64, "height": 32})";
  const std::optional<Camera> camera = findSceneCamera(scene);
  ASSERT_TRUE(camera.has_value());
  EXPECT_EQ(camera->position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(camera->vfovDegrees, 50);
  EXPECT_EQ(camera->width, 64);
  EXPECT_EQ(camera->height, 32);
  // A sidecar that exists but is bad is an error naming it, not "no camera".
  std::ofstream(dir / "room.camera.json") << "{\"position\": [0, 0, 1],\n \"look_at\": ";
  try {
    findSceneCamera(scene);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("room.camera.json"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rad
