// Lights besides emissive polygons on the command line: --lights FILE, the <scene>.lights.json
// sidecar, --sky and --sun; a bad lights file names the file, line and JSON pointer, exits 1 and
// writes nothing; the render methods that do not sample these lights refuse the scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// A grey floor facing up, no emitter, with a camera sidecar; returns the OBJ path.
fs::path writeFloorScene(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "floor.obj") << "mtllib floor.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
                                      "usemtl grey\nf 1 4 3 2\n";
  std::ofstream(dir / "floor.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
  std::ofstream(dir / "floor.camera.json")
      << R"({"position": [0, 2, 3], "look_at": [0, 0, 0], "up": [0, 1, 0], "vfov_degrees": 50,
             "width": 32, "height": 24})";
  return dir / "floor.obj";
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

struct BadLights {
  std::string name;
  std::string text;
  std::string location;  // ":line: /pointer" expected after the file name
  std::string phrase;
};
void PrintTo(const BadLights& c, std::ostream* os) { *os << c.name; }

class BadLightsFile : public ::testing::TestWithParam<BadLights> {};

TEST_P(BadLightsFile, NamesTheFileLineAndPointerExitsOneAndWritesNothing) {
  const BadLights& c = GetParam();
  const fs::path dir = testing::scratchPath("bad_lights_" + c.name);
  const fs::path scene = writeFloorScene(dir);
  const fs::path lights = dir / "bad.json";
  std::ofstream(lights) << c.text;
  const fs::path out = dir / "out";
  const auto result = testing::runRadiosity("solve " + scene.string() + " --lights " +
                                            lights.string() + " --out " + out.string());
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find(lights.string() + c.location), std::string::npos)
      << result.stderrText;
  EXPECT_NE(result.stderrText.find(c.phrase), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(out)) << "a failed run created " << out;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadLightsFile,
    ::testing::Values(
        BadLights{"unknown_type",
                  "{\"lights\": [\n {\"type\": \"sky\", \"radiance\": [1, 1, 1]},\n"
                  " {\"type\": \"area\"}]}",
                  ":3: /lights/1/type", "unknown light type \"area\""},
        BadLights{"environment",
                  "{\"lights\": [{\"type\": \"environment\", \"file\": \"sky.hdr\"}]}",
                  ":1: /lights/0/type", "not supported yet"},
        BadLights{"negative_intensity",
                  "{\"lights\": [\n {\"type\": \"point\",\n  \"position\": [0, 1, 0],\n"
                  "  \"intensity\": [1, -1, 1]}]}",
                  ":4: /lights/0/intensity", "must not be negative"},
        BadLights{"nan_direction",
                  "{\"lights\": [{\"type\": \"directional\", \"direction\": [0, NaN, 0], "
                  "\"irradiance\": [1, 1, 1]}]}",
                  ":1:", "malformed JSON"},
        BadLights{"zero_direction",
                  "{\"lights\": [{\"type\": \"directional\",\n \"direction\": [0, 0, 0], "
                  "\"irradiance\": [1, 1, 1]}]}",
                  ":2: /lights/0/direction", "non-zero direction"},
        BadLights{"unknown_key",
                  "{\"lights\": [{\"type\": \"point\", \"position\": [0, 1, 0], "
                  "\"intensity\": [1, 1, 1],\n \"power\": 3}]}",
                  ":2: /lights/0/power", "unknown key \"power\""},
        BadLights{"cone",
                  "{\"lights\": [{\"type\": \"spot\", \"position\": [0, 1, 0], \"direction\": "
                  "[0, -1, 0], \"intensity\": [1, 1, 1], \"cone_degrees\": 95}]}",
                  ":1: /lights/0/cone_degrees", "(0, 90]"},
        BadLights{"inner_wider",
                  "{\"lights\": [{\"type\": \"spot\", \"position\": [0, 1, 0], \"direction\": "
                  "[0, -1, 0], \"intensity\": [1, 1, 1], \"cone_degrees\": 20,\n "
                  "\"inner_cone_degrees\": 30}]}",
                  ":2: /lights/0/inner_cone_degrees", "must not exceed cone_degrees"},
        BadLights{"angular_diameter",
                  "{\"lights\": [{\"type\": \"directional\", \"direction\": [0, -1, 0], "
                  "\"irradiance\": [1, 1, 1], \"angular_diameter_degrees\": 90}]}",
                  ":1: /lights/0/angular_diameter_degrees", "[0, 90)"}),
    [](const ::testing::TestParamInfo<BadLights>& info) { return info.param.name; });

TEST(CliLights, TheSidecarLightsASceneWithoutEmittersAndSummaryCountsThem) {
  const fs::path dir = testing::scratchPath("lights_sidecar");
  const fs::path scene = writeFloorScene(dir);
  std::ofstream(dir / "floor.lights.json") << R"({"lights": [{"type": "sky", "radiance": [1, 1, 1]},
                        {"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1]}]})";
  const fs::path out = dir / "out";
  const auto result = testing::runRadiosity("solve " + scene.string() + " --out " + out.string() +
                                            " --elements 32 --sun 0 -1 0 100 100 100");
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_NE(result.stderrText.find("lights: 2 from " + (dir / "floor.lights.json").string() +
                                   " (beside the scene)"),
            std::string::npos)
      << result.stderrText;
  const auto summary = readJson(out / "summary.json");
  EXPECT_EQ(summary["lights"]["sky"], 1);
  EXPECT_EQ(summary["lights"]["point"], 1);
  EXPECT_EQ(summary["lights"]["directional"], 1);
  EXPECT_EQ(summary["lights"]["spot"], 0);
  EXPECT_GT(summary["lights"]["direct_light_rays"].get<double>(), 0);
  fs::remove_all(dir);
}

TEST(CliLights, WithoutLightsOrEmittersTheSceneIsRefused) {
  const fs::path dir = testing::scratchPath("lights_none");
  const fs::path scene = writeFloorScene(dir);
  const auto result =
      testing::runRadiosity("solve " + scene.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.stderrText.find("no emitter"), std::string::npos) << result.stderrText;
  fs::remove_all(dir);
}

TEST(CliLights, BadShortcutsAreErrors) {
  const fs::path dir = testing::scratchPath("lights_shortcuts");
  const fs::path scene = writeFloorScene(dir);
  for (const std::string args : {"--sky 1 -1 1", "--sun 0 0 0 1 1 1", "--sun 0 -1 0 nan 1 1"}) {
    const auto result = testing::runRadiosity("solve " + scene.string() + " --out " +
                                              (dir / "out").string() + " " + args);
    EXPECT_NE(result.exitCode, 0) << args;
    EXPECT_FALSE(fs::exists(dir / "out")) << args;
  }
  fs::remove_all(dir);
}

// Only the interpolated radiosity solution carries the lights today: every other way of
// rendering refuses the scene, before any work, rather than render it without them.
TEST(CliLights, MethodsThatDoNotSampleTheLightsRefuseAndWriteNothing) {
  const fs::path dir = testing::scratchPath("lights_render");
  const fs::path scene = writeFloorScene(dir);
  const std::string s = scene.string() + " --sky 1 1 1 ";
  for (const std::string& call : {"render " + s + "--method path",
                                  "render " + s + "--method radiosity --gather 4 --elements 32",
                                  "render " + s + "--method direct", "compare " + s,
                                  "bake " + s + "--gather 4 --elements 32"}) {
    const auto result = testing::runRadiosity(call + " --out " + (dir / "out").string());
    EXPECT_EQ(result.exitCode, 1) << call << "\n" << result.stderrText;
    EXPECT_NE(result.stderrText.find("does not sample point, spot, directional or sky lights"),
              std::string::npos)
        << call << "\n"
        << result.stderrText;
    EXPECT_FALSE(fs::exists(dir / "out")) << call;
  }
  const auto render =
      testing::runRadiosity("render " + s + "--method radiosity --gather 0 --elements 32 --out " +
                            (dir / "render").string());
  EXPECT_EQ(render.exitCode, 0) << render.stderrText;
  EXPECT_TRUE(fs::exists(dir / "render" / "render.png"));
  const auto bake =
      testing::runRadiosity("bake " + s + "--elements 32 --out " + (dir / "bake").string());
  EXPECT_EQ(bake.exitCode, 0) << bake.stderrText;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
