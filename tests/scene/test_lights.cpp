// The lights file reader: the values it keeps (unit directions, cone cosines, defaults), where a
// scene's lights come from (--lights, the sidecar, the shortcuts), and the JSON pointer → line
// lookup its errors use.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/scene/json_file.h"
#include "radiosity/scene/light_shapes.h"
#include "radiosity/scene/lights.h"
#include "tests/support/hdr_writer.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("radiosity_lights_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Lights, ReadsEveryTypeWithUnitDirectionsAndConeCosines) {
  const fs::path dir = scratch("types");
  std::ofstream(dir / "l.json") << R"({"comment": "x", "lights": [
    {"type": "point", "position": [1, 2, 3], "intensity": [4, 5, 6]},
    {"type": "spot", "position": [0, 1, 0], "direction": [0, -2, 0], "intensity": [1, 1, 1],
     "cone_degrees": 60, "inner_cone_degrees": 45},
    {"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "intensity": [1, 1, 1],
     "cone_degrees": 30},
    {"type": "directional", "direction": [0, 0, -5], "irradiance": [7, 8, 9],
     "angular_diameter_degrees": 0.53},
    {"type": "sky", "radiance": [0.1, 0.2, 0.3], "up": [0, 0, 3], "comment": "blue"}]})";
  const std::vector<Light> lights = loadLights((dir / "l.json").string());
  ASSERT_EQ(lights.size(), 5u);
  EXPECT_EQ(lights[0].type, LightType::Point);
  EXPECT_EQ(lights[0].position, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(lights[0].intensity.b, 6);
  EXPECT_EQ(lights[1].direction, Eigen::Vector3d(0, -1, 0));
  EXPECT_NEAR(lights[1].cosOuter, 0.5, 1e-15);
  EXPECT_NEAR(lights[1].cosInner, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(lights[2].cosInner, lights[2].cosOuter);  // no inner cone: a hard edge
  EXPECT_EQ(lights[3].direction, Eigen::Vector3d(0, 0, -1));
  EXPECT_EQ(lights[3].angularDiameterDegrees, 0.53);
  EXPECT_EQ(lights[4].up, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(lightTypeName(lights[4].type), "sky");
  fs::remove_all(dir);
}

TEST(Lights, ErrorsNameTheFileLineAndPointer) {
  const fs::path dir = scratch("errors");
  const std::string path = (dir / "l.json").string();
  std::ofstream(path) << "{\"lights\": [\n  {\"type\": \"sky\", \"radiance\": [1, 1, 1]},\n"
                         "  {\"type\": \"point\", \"position\": [0, 0, 0],\n"
                         "   \"intensity\": [1, 1, -1]}]}";
  try {
    loadLights(path);
    FAIL() << "accepted a negative intensity";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(std::string(e.what()).find("/lights/1/intensity"), std::string::npos) << e.what();
  }
  std::ofstream(path) << R"({"lights": [{"type": "point", "position": [0, 0, 0]}]})";
  EXPECT_THROW(loadLights(path), InputError);  // missing intensity
  std::ofstream(path) << R"({"light": []})";
  EXPECT_THROW(loadLights(path), InputError);
  EXPECT_THROW(loadLights((dir / "missing.json").string()), InputError);
  fs::remove_all(dir);
}

TEST(Lights, ReadsLightGroupsAndRefusesAnEmptyOrNonStringGroup) {
  const fs::path dir = scratch("groups");
  const std::string path = (dir / "l.json").string();
  std::ofstream(path) << R"({"lights": [
    {"type": "point", "position": [0, 1, 0], "intensity": [1, 1, 1], "group": "desk"},
    {"type": "sky", "radiance": [1, 1, 1]}]})";
  const std::vector<Light> lights = loadLights(path);
  EXPECT_EQ(lights[0].group, "desk");
  EXPECT_EQ(lights[1].group, "");  // a group of its own
  EXPECT_EQ(skyLight(Rgb::all(1)).group, "sky");
  EXPECT_EQ(sunLight({0, -1, 0}, Rgb::all(1)).group, "sun");
  for (const char* bad : {R"("")", "3", "[\"a\"]"}) {
    std::ofstream(path) << "{\"lights\": [\n  {\"type\": \"point\", \"position\": [0, 1, 0],\n"
                           "   \"intensity\": [1, 1, 1], \"group\": "
                        << bad << "}]}";
    try {
      loadLights(path);
      FAIL() << "accepted the group " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 3) << bad;
      EXPECT_NE(std::string(e.what()).find("/lights/0/group"), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

TEST(Lights, ReadsTheCieOvercastSkyAndRefusesUnknownModelsAndTheOtherModelsRadiance) {
  const fs::path dir = scratch("overcast");
  const std::string path = (dir / "l.json").string();
  std::ofstream(path) << R"({"lights": [
    {"type": "sky", "model": "cie_overcast", "zenith_radiance": [1, 2, 3]},
    {"type": "sky", "model": "uniform", "radiance": [4, 5, 6]}]})";
  const std::vector<Light> lights = loadLights(path);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].skyModel, SkyModel::CieOvercast);
  EXPECT_EQ(lights[0].radiance.b, 3);
  EXPECT_EQ(lights[1].skyModel, SkyModel::Uniform);
  struct Bad {
    std::string text, pointer, phrase;
  };
  for (const Bad& bad : std::vector<Bad>{
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": \"cie_hazy\", \"radiance\": [1, 1, "
            "1]}]}",
            "/lights/0/model", "unknown sky model \"cie_hazy\""},
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": 3, \"radiance\": [1, 1, 1]}]}",
            "/lights/0/model", "must be a string"},
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": \"cie_overcast\", \"radiance\": [1, 1, "
            "1]}]}",
            "/lights/0/radiance", "takes \"zenith_radiance\""},
           {"{\"lights\": [\n{\"type\": \"sky\", \"zenith_radiance\": [1, 1, 1]}]}",
            "/lights/0/zenith_radiance", "takes \"radiance\""},
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": \"cie_overcast\"}]}", "/lights/0",
            "missing key \"zenith_radiance\""},
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": \"cie_overcast\", "
            "\"zenith_radiance\": [1, -1, 1]}]}",
            "/lights/0/zenith_radiance", "must not be negative"}}) {
    std::ofstream(path) << bad.text;
    try {
      loadLights(path);
      ADD_FAILURE() << "accepted " << bad.text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.line(), 2) << bad.text;
      EXPECT_NE(std::string(e.what()).find(bad.pointer + ": "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(bad.phrase), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

// An error that must name the lights file, the line and the JSON pointer, and say `phrase`.
void expectRefused(const std::string& path, const std::string& text, int line,
                   const std::string& pointer, const std::string& phrase) {
  std::ofstream(path) << text;
  try {
    loadLights(path);
    ADD_FAILURE() << "accepted " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), line) << text;
    EXPECT_NE(std::string(e.what()).find(pointer + ": "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

TEST(Lights, ReadsTheCieClearSkyWithItsSunAndRefusesItWithoutOne) {
  const fs::path dir = scratch("clear");
  const std::string path = (dir / "l.json").string();
  std::ofstream(path) << R"({"lights": [
    {"type": "sky", "model": "cie_clear", "zenith_radiance": [1, 2, 3],
     "sun_direction": [0, -1, -1], "up": [0, 2, 0]}]})";
  const std::vector<Light> lights = loadLights(path);
  ASSERT_EQ(lights.size(), 1u);
  EXPECT_EQ(lights[0].skyModel, SkyModel::CieClear);
  EXPECT_LT((lights[0].direction - Eigen::Vector3d(0, -1, -1).normalized()).norm(), 1e-15);
  EXPECT_EQ(lights[0].up, Eigen::Vector3d(0, 1, 0));
  ASSERT_NE(lights[0].map, nullptr);                           // its sampling table
  EXPECT_NEAR(skyRadiance(lights[0], {0, 1, 0}).b, 3, 1e-12);  // the zenith's radiance
  const std::string head = "{\"lights\": [\n{\"type\": \"sky\", ";
  expectRefused(path, head + "\"model\": \"cie_clear\", \"zenith_radiance\": [1, 1, 1]}]}", 2,
                "/lights/0", "missing key \"sun_direction\"");
  expectRefused(path,
                head +
                    "\"model\": \"cie_clear\", \"zenith_radiance\": [1, 1, 1], "
                    "\"sun_direction\": [0, 1, 1]}]}",
                2, "/lights/0/sun_direction", "above the horizon");
  expectRefused(path,
                head +
                    "\"model\": \"cie_clear\", \"zenith_radiance\": [1, 1, 1], "
                    "\"sun_direction\": [0, 0, 0]}]}",
                2, "/lights/0/sun_direction", "non-zero direction");
  expectRefused(path, head + "\"radiance\": [1, 1, 1], \"sun_direction\": [0, -1, 0]}]}", 2,
                "/lights/0/sun_direction", "only a cie_clear sky");
  fs::remove_all(dir);
}

TEST(Lights, ReadsAnEnvironmentImageRelativeToTheLightsFileScaled) {
  const fs::path dir = scratch("environment");
  fs::create_directories(dir / "maps");
  // 4 × 2: the top row 1, 2, 3, 4 (grey), the bottom row 0.5.
  testing::writeHdr((dir / "maps" / "sky.hdr").string(), 4, 2,
                    {Rgb::all(1), Rgb::all(2), Rgb::all(3), Rgb::all(4), Rgb::all(0.5),
                     Rgb::all(0.5), Rgb::all(0.5), Rgb::all(0.5)});
  const std::string path = (dir / "l.json").string();
  std::ofstream(path) << R"({"lights": [
    {"type": "environment", "file": "maps/sky.hdr", "up": [0, 0, 1], "scale": 2},
    {"type": "environment", "file": "maps/sky.hdr", "comment": "defaults: up +y, scale 1"}]})";
  const std::vector<Light> lights = loadLights(path);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].type, LightType::Environment);
  EXPECT_EQ(lightTypeName(lights[0].type), "environment");
  ASSERT_NE(lights[0].map, nullptr);
  EXPECT_EQ(lights[0].map->width(), 4);
  EXPECT_EQ(lights[0].map->height(), 2);
  EXPECT_EQ(lights[0].up, Eigen::Vector3d(0, 0, 1));
  // Up +z (Blender's frame): u = 0.5 − atan2(y, x)/2π, so a little off +y towards +x is just
  // right of the quarter column (the second texel, 2 × scale 2), a little off +x towards −y just
  // right of the centre (the third, 3 × 2); the ground half is the bottom row.
  EXPECT_EQ(skyRadiance(lights[0], Eigen::Vector3d(0.2, 1, 0.5).normalized()).r, 4);
  EXPECT_EQ(skyRadiance(lights[0], Eigen::Vector3d(1, -0.1, 0.5).normalized()).r, 6);
  EXPECT_EQ(skyRadiance(lights[0], Eigen::Vector3d(0.3, 0.2, -0.5).normalized()).r, 1);
  EXPECT_EQ(lights[1].up, Eigen::Vector3d(0, 1, 0));
  // Up +y: the quarter column looks along −z (the three-quarter one along +z), so −z turned a
  // little towards −x is left of it (the first texel), +z turned towards +x left of the
  // three-quarter one.
  EXPECT_EQ(skyRadiance(lights[1], Eigen::Vector3d(-0.2, 0.5, -1).normalized()).r, 1);
  EXPECT_EQ(skyRadiance(lights[1], Eigen::Vector3d(0.2, 0.5, 1).normalized()).r, 3);
  fs::remove_all(dir);
}

TEST(Lights, RefusesBadEnvironmentEntriesNamingTheFileAndPointer) {
  const fs::path dir = scratch("environment_bad");
  testing::writeHdr((dir / "sky.hdr").string(), 2, 1, {Rgb::all(1), Rgb::all(1)});
  std::ofstream(dir / "not_an_image.hdr") << "hello";
  const std::string path = (dir / "l.json").string();
  const std::string head = "{\"lights\": [\n{\"type\": \"environment\", ";
  expectRefused(path, head + "\"file\": \"missing.hdr\"}]}", 2, "/lights/0/file",
                (dir / "missing.hdr").string() + ": cannot open the environment image");
  expectRefused(path, head + "\"file\": \"not_an_image.hdr\"}]}", 2, "/lights/0/file",
                (dir / "not_an_image.hdr").string() + ": not a readable image");
  expectRefused(path, head + "\"file\": \".\"}]}", 2, "/lights/0/file",
                "cannot open the environment image");
  expectRefused(path, head + "\"file\": \"sky.hdr\", \"scale\": -1}]}", 2, "/lights/0/scale",
                "must not be negative");
  // JSON holds no NaN or infinity: such a scale never parses.
  for (const char* scale : {"NaN", "1e999"}) {
    std::ofstream(path) << head + "\"file\": \"sky.hdr\", \"scale\": " + scale + "}]}";
    EXPECT_THROW(loadLights(path), InputError) << scale;
  }
  expectRefused(path, head + "\"file\": \"sky.hdr\", \"scale\": \"2\"}]}", 2, "/lights/0/scale",
                "must be a number");
  expectRefused(path, head + "\"file\": \"sky.hdr\", \"rotation\": 90}]}", 2, "/lights/0/rotation",
                "unknown key \"rotation\"");
  expectRefused(path, head + "\"file\": 3}]}", 2, "/lights/0/file", "must be the image's file");
  expectRefused(path, head + "\"scale\": 1}]}", 2, "/lights/0", "missing key \"file\"");
  expectRefused(path, head + "\"file\": \"sky.hdr\", \"up\": [0, 0, 0]}]}", 2, "/lights/0/up",
                "non-zero direction");
  fs::remove_all(dir);
}

TEST(Lights, TheSidecarIsReadUnlessAFileIsGivenAndShortcutsAreAdded) {
  const fs::path dir = scratch("sidecar");
  const std::string scene = (dir / "room.obj").string();
  EXPECT_TRUE(findSceneLights(scene, {}, false).empty());
  EXPECT_EQ(lightsSidecarPath(scene), (dir / "room.lights.json").string());
  std::ofstream(dir / "room.lights.json")
      << R"({"lights": [{"type": "sky", "radiance": [1, 1, 1]}]})";
  std::ofstream(dir / "other.json")
      << R"({"lights": [{"type": "point", "position": [0, 0, 0], "intensity": [1, 1, 1]}]})";
  EXPECT_EQ(findSceneLights(scene, {}, false).at(0).type, LightType::Sky);
  LightInput input{(dir / "other.json").string(), {sunLight({0, -1, 0}, {1, 1, 1})}};
  const auto lights = findSceneLights(scene, input, false);
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].type, LightType::Point);  // the file given, not the sidecar
  EXPECT_EQ(lights[1].type, LightType::Directional);
  EXPECT_EQ(lights[1].angularDiameterDegrees, 0.53);
  EXPECT_THROW(skyLight({1, -1, 1}), InputError);
  EXPECT_THROW(sunLight({0, 0, 0}, {1, 1, 1}), InputError);
  EXPECT_THROW(sunLight({0, -1, 0}, {NAN, 1, 1}), InputError);
  fs::remove_all(dir);
}

TEST(JsonPointerLine, FindsMembersAndElementsOnTheirLines) {
  const std::string text =
      "{\"a\": [1,\n 2, {\"b\": \"x]}\\\"\",\n \"c\": [\n[], {}]}],\n \"d/e~f\": 3}";
  EXPECT_EQ(lineOfPointer(text, ""), 1);
  EXPECT_EQ(lineOfPointer(text, "/a/1"), 2);
  EXPECT_EQ(lineOfPointer(text, "/a/2/b"), 2);
  EXPECT_EQ(lineOfPointer(text, "/a/2/c"), 3);
  EXPECT_EQ(lineOfPointer(text, "/a/2/c/1"), 4);
  EXPECT_EQ(lineOfPointer(text, "/d~1e~0f"), 5);
  EXPECT_EQ(lineOfPointer(text, "/a/7"), 0);
  EXPECT_EQ(lineOfPointer(text, "/zz"), 0);
  EXPECT_EQ(lineOfPointer(text, "/a/x"), 0);
  EXPECT_EQ(lineOfPointer(text, "a"), 0);
}

}  // namespace
}  // namespace rad

namespace rad {
namespace {

void expectRgb(const Rgb& actual, const Rgb& expected) {
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(actual[c], expected[c]) << "channel " << c;
}

// relight's light scale: every strength a light has is multiplied, per channel, and nothing else
// changes — a clear sky's table too, which its sampling and the renders read.
TEST(Lights, ScaledLightMultipliesEveryStrengthPerChannel) {
  const Rgb k{2, 0.5, 0};
  Light spot;
  spot.type = LightType::Spot;
  spot.intensity = {0.1, 0.2, 0.3};
  spot.cosOuter = 0.5;
  const Light scaledSpot = scaledLight(spot, k);
  expectRgb(scaledSpot.intensity, {0.2, 0.1, 0});
  EXPECT_EQ(scaledSpot.cosOuter, 0.5);
  expectRgb(scaledLight(sunLight({0.3, -1, 0.25}, {8, 7.6, 6.8}), k).irradiance, {16, 3.8, 0});
  const Light sky = cieClearSky({1, 2, 3}, Eigen::Vector3d(0.3, -1, 0.25).normalized());
  const Rgb before = sky.map->texels()[0];
  const Light scaledSky = scaledLight(sky, k);
  expectRgb(scaledSky.radiance, {2, 1, 0});
  ASSERT_TRUE(scaledSky.map);
  ASSERT_EQ(scaledSky.map->texels().size(), sky.map->texels().size());
  for (size_t i = 0; i < sky.map->texels().size(); ++i)
    expectRgb(scaledSky.map->texels()[i], sky.map->texels()[i] * k);
  expectRgb(sky.map->texels()[0], before);  // the original is left as it was
}

}  // namespace
}  // namespace rad
