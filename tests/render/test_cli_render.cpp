// `radiosity render` end to end: outputs, exact emitter radiance in the EXR, bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "radiosity/output/image_io.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kMirrorRoom = std::string(RADIOSITY_DATA_DIR) + "/tests/mirror_room.obj";
// Looking straight up at the light (0.3 × 0.3 at 0.499 above the camera: ±16.7°) with a 20°
// field of view: every sample of every pixel sees the emitter's front.
const std::string kLookAtLight =
    "--position 0.5 0.5 0.5 --look-at 0.5 1 0.5 --up 0 0 1 --vfov 20 --width 8 --height 6 -q";
// The solve's size, for the methods that solve (solve options are errors for the others).
std::string solveSize(const std::string& method) {
  return method == "radiosity" ? " --elements 200 --rays 64" : "";
}

class CliRender : public ::testing::TestWithParam<std::string> {};

// The light has Kd 0 and Ke 10: its radiance is exactly 10 W·m⁻²·sr⁻¹, and the EXR keeps floats
// exactly, so every pixel reads back exactly 10 for both methods.
TEST_P(CliRender, EmitterPixelsHoldExactlyKeAfterTheExrRoundTrip) {
  const fs::path out = scratchPath("render_" + GetParam());
  const auto r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --method " +
                              GetParam() + " --spp 5 " + kLookAtLight + solveSize(GetParam()));
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const ImageRgb image = readExr((out / "render.exr").string());
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 6);
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], 10.0);
  EXPECT_TRUE(fs::exists(out / "render.png"));
  std::ifstream in(out / "render.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["method"], GetParam());
  EXPECT_EQ(report["rays"]["camera"], 8 * 6 * 5);
  EXPECT_GT(report["rays_per_second"].get<double>(), 0);
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Methods, CliRender, ::testing::Values("radiosity", "path"));

TEST(CliRenderReport, SkippedWorkIsListed) {
  const fs::path out = scratchPath("render_skips");
  const auto r = runRadiosity("render " + std::string(RADIOSITY_DATA_DIR) +
                              "/tests/furnace_box.obj --out " + out.string() +
                              " --position 0.5 0.5 0.5 --look-at 0.5 0.5 1 --width 4 --height 4 "
                              "--gather 2 --spp 1 --elements 50 --rays 16 -q");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  std::ifstream in(out / "render.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("specular branch"), std::string::npos);
  fs::remove_all(out);
}

TEST(CliRenderErrors, BadCameraFileNamesFileAndLineAndWritesNothing) {
  const fs::path out = scratchPath("render_bad_camera");
  const fs::path camera = scratchPath("bad_camera.json");
  {
    std::ofstream f(camera);
    f << "{\n  \"position\": [0.5, 0.5, 0.5],\n  \"look_at\": [0.5, 0.5,, 1]\n}\n";
  }
  const auto r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --camera " +
                              camera.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find(camera.string() + ":3:"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr"));
  EXPECT_FALSE(fs::exists(out / "render.json"));
  fs::remove(camera);
}

TEST(CliRenderErrors, NoCameraAndBadOptionsAreErrors) {
  const fs::path out = scratchPath("render_no_camera");
  // furnace_box has no sidecar camera.
  auto r = runRadiosity("render " + std::string(RADIOSITY_DATA_DIR) +
                        "/tests/furnace_box.obj --out " + out.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("no camera"), std::string::npos) << r.stderrText;
  r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --method raytrace");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("--method"), std::string::npos) << r.stderrText;
  r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --spp 0");
  EXPECT_EQ(r.exitCode, 2);
  r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --vfov 200");
  EXPECT_EQ(r.exitCode, 1);
  r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --light-rays -1");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("--light-rays must be >= 0"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr"));
}

}  // namespace
}  // namespace rad
