// The scene's own UVs as lightmap UVs (bake --use-scene-uvs): what passes, and the face line each
// rejection names.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// Two unit squares side by side in 3D (lines 2-7 hold v); the caller adds `vt` lines and faces.
const char* const kHead =
    "mtllib m.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n";

class LightmapUvCheck : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("radiosity_uvcheck_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "m.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The scene from kHead + `vts` + "usemtl lamp" + `faces`: with 8 `vt` lines the faces are on
  // lines 17 and 18.
  Scene scene(const std::string& vts, const std::string& faces) {
    const fs::path path = dir_ / "s.obj";
    std::ofstream(path) << kHead << vts << "usemtl lamp\n" << faces;
    return loadObjScene(path.string());
  }

  void expectError(const Scene& s, int line, const std::string& phrase) {
    try {
      checkLightmapUvs(s);
      FAIL() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.line(), line) << what;
      EXPECT_EQ(what.rfind(s.sourcePath, 0), 0u) << what;
      EXPECT_NE(what.find("--use-scene-uvs"), std::string::npos) << what;
      EXPECT_NE(what.find(phrase), std::string::npos) << what;
    }
  }

  fs::path dir_;
};

// Left square in [0, 0.4]², right square in [0.5, 0.9] x [0, 0.4]: apart.
const char* const kApart = "vt 0 0\nvt 0.4 0\nvt 0.4 0.4\nvt 0 0.4\n";
const char* const kFaces = "f 1/1 2/2 3/3 4/4\nf 2/5 5/6 6/7 3/8\n";

TEST_F(LightmapUvCheck, SeparateAndTouchingIslandsPass) {
  EXPECT_NO_THROW(checkLightmapUvs(
      scene(std::string(kApart) + "vt 0.5 0\nvt 0.9 0\nvt 0.9 0.4\nvt 0.5 0.4\n", kFaces)));
  // The right square continues the left one's UVs: they share a UV edge, which is allowed.
  EXPECT_NO_THROW(checkLightmapUvs(
      scene(std::string(kApart) + "vt 0.4 0\nvt 0.8 0\nvt 0.8 0.4\nvt 0.4 0.4\n", kFaces)));
  EXPECT_NO_THROW(checkLightmapUvs(
      loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/tests/furnace_box_uv.obj")));
}

TEST_F(LightmapUvCheck, OverlappingFacesNameBothLines) {
  const Scene s =
      scene(std::string(kApart) + "vt 0.3 0.3\nvt 0.9 0.3\nvt 0.9 0.9\nvt 0.3 0.9\n", kFaces);
  expectError(s, 18, "overlaps the face at line 17");
}

TEST_F(LightmapUvCheck, FoldedFaceIsRefused) {
  // A bow tie: the quad's two triangles cover each other in UV.
  const Scene s =
      scene(std::string(kApart) + "vt 0.5 0\nvt 0.9 0.4\nvt 0.9 0\nvt 0.5 0.4\n", kFaces);
  expectError(s, 18, "folds over itself");
}

TEST_F(LightmapUvCheck, OutOfRangeAndDegenerateUvsAreRefused) {
  expectError(scene(std::string(kApart) + "vt 0.5 0\nvt 1.25 0\nvt 0.9 0.4\nvt 0.5 0.4\n", kFaces),
              18, "(1.25, 0) is outside [0, 1]");
  expectError(
      scene(std::string(kApart) + "vt 0.5 -0.5\nvt 0.9 0\nvt 0.9 0.4\nvt 0.5 0.4\n", kFaces), 18,
      "outside [0, 1]");
  // All four corners on one line in UV.
  expectError(
      scene(std::string(kApart) + "vt 0.5 0.5\nvt 0.6 0.6\nvt 0.7 0.7\nvt 0.8 0.8\n", kFaces), 18,
      "zero area in texture space");
}

TEST_F(LightmapUvCheck, MissingUvsAreRefused) {
  const Scene none = loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/tests/furnace_box.obj");
  expectError(none, 0, "the scene has no texture coordinates");
  expectError(scene(kApart, "f 1/1 2/2 3/3 4/4\nf 2 5 6 3\n"), 14, "1 of 2 faces lack them");
  // OBJ lets a face name a `vt` for some corners only: that face has no UVs either.
  expectError(scene(kApart, "f 1/1 2/2 3/3 4/4\nf 2/2 5 6/3 3/3\n"), 14,
              "face lacks texture coordinates at some corner");
}

}  // namespace
}  // namespace rad
