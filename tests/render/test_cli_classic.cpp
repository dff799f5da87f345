// The classic methods and `radiosity compare` end to end: every method runs from the command
// line and says which paths it captures, compare writes its contact sheet and every EXR, and
// unknown methods and impossible options are clear errors that write nothing.
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

const std::string kData = std::string(RADIOSITY_DATA_DIR) + "/tests/";
const std::string kMirrorRoom = kData + "mirror_room.obj";
const std::string kSmall = " --width 12 --height 10 -q";
// The solve's size, where a radiosity method runs (solve options are errors for the others).
const std::string kSmallSolve = " --elements 150 --rays 32 --gather 4";

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// PNG: width and height are the big-endian words at bytes 16 and 20 (the IHDR chunk).
std::pair<int, int> pngSize(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), 24);
  auto word = [&](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  return {word(16), word(20)};
}

class CliClassicMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(CliClassicMethod, RendersAndReportsItsPaths) {
  const fs::path out = scratchPath("classic_" + GetParam());
  const auto r = runRadiosity("render " + kMirrorRoom + " --out " + out.string() + " --method " +
                              GetParam() + " --spp 2" + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const ImageRgb image = readExr((out / "render.exr").string());
  EXPECT_EQ(image.width, 12);
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += p.sum();
  EXPECT_GT(sum, 0);  // the room is lit
  const auto report = readJson(out / "render.json");
  EXPECT_EQ(report["method"], GetParam());
  EXPECT_FALSE(report["paths"].get<std::string>().empty());
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Methods, CliClassicMethod,
                         ::testing::Values("direct", "whitted", "distribution"));

TEST(CliCompare, WritesTheContactSheetAndEveryExr) {
  const fs::path out = scratchPath("compare_all");
  const auto r = runRadiosity("compare " + kMirrorRoom + " --out " + out.string() + " --spp 2" +
                              kSmall + kSmallSolve);
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const auto report = readJson(out / "compare.json");
  ASSERT_GE(report["methods"].size(), 5u);
  std::vector<std::string> names;
  for (const auto& m : report["methods"]) {
    names.push_back(m["method"]);
    const ImageRgb image = readExr((out / m["exr"].get<std::string>()).string());
    EXPECT_EQ(image.width, 12);
    EXPECT_EQ(image.height, 10);
    EXPECT_EQ(m["samples_per_pixel"], 2);
    EXPECT_FALSE(m["paths"].get<std::string>().empty());
  }
  for (const char* expected : {"direct", "whitted", "distribution", "path", "radiosity"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  // Three tiles per row by default: the sheet is wider than three images and taller than two
  // (the labels sit under each).
  const auto [w, h] = pngSize(out / "compare.png");
  EXPECT_GT(w, 3 * 12);
  EXPECT_GT(h, 2 * 10);
  fs::remove_all(out);
}

TEST(CliCompare, ASubsetInTheGivenOrder) {
  const fs::path out = scratchPath("compare_subset");
  const auto r = runRadiosity("compare " + kMirrorRoom + " --out " + out.string() +
                              " --methods whitted,direct --columns 1" + kSmall);
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const auto report = readJson(out / "compare.json");
  ASSERT_EQ(report["methods"].size(), 2u);
  EXPECT_EQ(report["methods"][0]["method"], "whitted");
  EXPECT_EQ(report["methods"][1]["method"], "direct");
  EXPECT_FALSE(fs::exists(out / "path.exr"));
  const auto [w, h] = pngSize(out / "compare.png");
  EXPECT_LT(w, 2 * 12 + 40);  // one column
  EXPECT_GT(h, 2 * 10);
  fs::remove_all(out);
}

struct BadCall {
  const char* name;
  const char* arguments;  // after "<command> SCENE --out DIR"
  const char* command;
  int exitCode;
  const char* words;
};

class CliClassicErrors : public ::testing::TestWithParam<BadCall> {};

TEST_P(CliClassicErrors, ClearMessageAndNothingWritten) {
  const BadCall& bad = GetParam();
  const fs::path out = scratchPath(std::string("classic_bad_") + bad.name);
  fs::remove_all(out);
  const auto r = runRadiosity(std::string(bad.command) + " " + kMirrorRoom + " --out " +
                              out.string() + " " + bad.arguments);
  EXPECT_EQ(r.exitCode, bad.exitCode) << r.stderrText;
  EXPECT_NE(r.stderrText.find(bad.words), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr"));
  EXPECT_FALSE(fs::exists(out / "compare.png"));
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliClassicErrors,
    ::testing::Values(
        BadCall{"render_method", "--method raytrace", "render", 1,
                "unknown --method 'raytrace' (expected direct | whitted"},
        BadCall{"compare_method", "--methods direct,raytrace", "compare", 1,
                "unknown --method 'raytrace'"},
        BadCall{"compare_twice", "--methods direct,direct", "compare", 1, "twice"},
        BadCall{"compare_columns", "--columns 0", "compare", 1, "--columns must be >= 1"},
        BadCall{"compare_spp", "--spp 0", "compare", 2, "--spp"},
        BadCall{"compare_exposure", "--exposure -1", "compare", 1, "--exposure must be > 0"},
        BadCall{"compare_no_camera", "--camera /nonexistent/camera.json", "compare", 1,
                "cannot open camera file"}),
    [](const ::testing::TestParamInfo<BadCall>& info) { return std::string(info.param.name); });

// The motion sidecar: distribution renders it; a bad object name fails before any work, naming
// the camera file and the line; other methods say they skip it.
TEST(CliMotionBlur, DistributionRendersTheSidecarsMotion) {
  const fs::path out = scratchPath("classic_motion");
  const auto r = runRadiosity("render " + kData + "motion_blur.obj --out " + out.string() +
                              " --method distribution --spp 8 --width 16 --height 16 -q");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const auto report = readJson(out / "render.json");
  EXPECT_EQ(report["motion_blur"]["moving_objects"], 1);
  fs::remove_all(out);

  const auto p = runRadiosity("render " + kData + "motion_blur.obj --out " + out.string() +
                              " --method path --spp 1 --width 4 --height 4 -q");
  ASSERT_EQ(p.exitCode, 0) << p.stderrText;
  const std::string text = readJson(out / "render.json")["skipped"].dump();
  EXPECT_NE(text.find("motion blur"), std::string::npos) << text;
  fs::remove_all(out);
}

TEST(CliMotionBlur, UnknownObjectNamesTheCameraFileAndLine) {
  const fs::path out = scratchPath("classic_motion_bad");
  const fs::path camera = scratchPath("classic_motion_bad.json");
  {
    std::ofstream f(camera);
    f << "{\"position\": [0, 0, -1], \"look_at\": [0, 0, 1], \"up\": [0, 1, 0],\n"
         " \"vfov_degrees\": 30, \"width\": 8, \"height\": 8,\n"
         " \"motion\": [\n"
         "   {\"object\": \"mover\", \"velocity\": [1, 0, 0]},\n"
         "   {\"object\": \"nothing\", \"velocity\": [1, 0, 0]}]}\n";
  }
  const auto r = runRadiosity("render " + kData + "motion_blur.obj --out " + out.string() +
                              " --method distribution --camera " + camera.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find(camera.string() + ":5:"), std::string::npos) << r.stderrText;
  EXPECT_NE(r.stderrText.find("'nothing'"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr"));
  // compare checks it before its first render, whatever the order of the methods.
  const auto c = runRadiosity("compare " + kData + "motion_blur.obj --out " + out.string() +
                              " --methods path,distribution --camera " + camera.string());
  EXPECT_EQ(c.exitCode, 1);
  EXPECT_NE(c.stderrText.find(camera.string() + ":5:"), std::string::npos) << c.stderrText;
  EXPECT_EQ(c.stderrText.find("render (path"), std::string::npos) << c.stderrText;
  EXPECT_FALSE(fs::exists(out / "compare.png"));
  fs::remove_all(out);
  fs::remove(camera);
}

}  // namespace
}  // namespace rad
