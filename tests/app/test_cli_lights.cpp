// Lights besides emissive polygons on the command line: --lights FILE, the <scene>.lights.json
// sidecar, --sky and --sun; a bad lights file names the file, line and JSON pointer, exits 1 and
// writes nothing; every render method renders a scene lit only by these lights.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "radiosity/output/image_io.h"
#include "tests/support/hdr_writer.h"
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
                  ":1: /lights/0/file", "sky.hdr: cannot open the environment image"},
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

// An environment image beside the lights file: radiance 1 above the horizon, 0.25 below. The
// solve counts it; the floor (ρ = 0.5) sees the upper half only, so `direct` (the map's irradiance
// table, within 1%) shows ρL = 0.5 at the centre, and the corner, past the floor and below the
// horizon, sees the image's ground half exactly: 0.25, not the sky's black ground.
TEST(CliLights, AnEnvironmentImageLightsTheSceneAndShowsItsGroundHalf) {
  const fs::path dir = testing::scratchPath("lights_environment");
  const fs::path scene = writeFloorScene(dir);
  std::vector<Rgb> texels(16 * 8, Rgb::all(0.25));
  std::fill(texels.begin(), texels.begin() + 16 * 4, Rgb::all(1));
  fs::create_directories(dir / "maps");
  testing::writeHdr((dir / "maps" / "sky.hdr").string(), 16, 8, texels);
  std::ofstream(dir / "floor.lights.json")
      << R"({"lights": [{"type": "environment", "file": "maps/sky.hdr"}]})";
  const auto solve = testing::runRadiosity("solve " + scene.string() + " --out " +
                                           (dir / "solve").string() + " --elements 32");
  ASSERT_EQ(solve.exitCode, 0) << solve.stderrText;
  EXPECT_EQ(readJson(dir / "solve" / "summary.json")["lights"]["environment"], 1);
  for (const std::string method : {"direct", "path --spp 4"}) {
    const fs::path out = dir / "out";
    const auto result = testing::runRadiosity("render " + scene.string() + " --method " + method +
                                              " --out " + out.string());
    ASSERT_EQ(result.exitCode, 0) << method << "\n" << result.stderrText;
    const ImageRgb image = readExr((out / "render.exr").string());
    for (int c = 0; c < 3; ++c) {
      if (method == "direct") {
        EXPECT_NEAR(image.at(16, 12)[c], 0.5, 0.005);
      }
      EXPECT_NEAR(image.at(0, 0)[c], 0.25, 1e-6) << method;
    }
    fs::remove_all(out);
  }
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
    // Refused by the option's own check while the command line is read: bad input (1), named.
    EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.stderrText;
    EXPECT_NE(result.stderrText.find(args.substr(0, 5) + ":"), std::string::npos)
        << args << "\n"
        << result.stderrText;
    EXPECT_FALSE(fs::exists(dir / "out")) << args;
  }
  fs::remove_all(dir);
}

// Every method renders a scene lit only by lights: the floor (ρ = 0.5) under a uniform sky of
// radiance 1 has radiance ρL = 0.5 in every method (each samples the sky, or takes it in closed
// form, exactly here: the floor sees nothing but sky); the view's upper corner looks past the
// floor, below the horizon, at the black ground. compare and bake's per-texel gather run too.
TEST(CliLights, EveryMethodRendersASceneLitOnlyByASky) {
  const fs::path dir = testing::scratchPath("lights_render");
  const fs::path scene = writeFloorScene(dir);
  const std::string s = scene.string() + " --sky 1 1 1 ";
  for (const std::string args :
       {"--method direct", "--method whitted", "--method distribution --spp 4",
        "--method path --spp 4", "--method bdpt --spp 4",
        "--method radiosity --gather 0 --elements 32",
        "--method radiosity --gather 4 --spp 4 --elements 32"}) {
    const fs::path out = dir / "out";
    const auto result = testing::runRadiosity("render " + s + args + " --out " + out.string());
    ASSERT_EQ(result.exitCode, 0) << args << "\n" << result.stderrText;
    const ImageRgb image = readExr((out / "render.exr").string());
    ASSERT_EQ(image.width, 32);
    const Rgb centre = image.at(16, 12), corner = image.at(0, 0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(centre[c], 0.5, 1e-3) << args;
      EXPECT_EQ(corner[c], 0) << args;
    }
    fs::remove_all(out);
  }
  const auto compare = testing::runRadiosity("compare " + s + "--spp 2 --elements 32 --out " +
                                             (dir / "compare").string());
  EXPECT_EQ(compare.exitCode, 0) << compare.stderrText;
  const auto bake = testing::runRadiosity("bake " + s + "--gather 4 --elements 32 --out " +
                                          (dir / "bake").string());
  EXPECT_EQ(bake.exitCode, 0) << bake.stderrText;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
