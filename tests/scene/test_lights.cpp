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
#include "radiosity/scene/lights.h"

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
           {"{\"lights\": [\n{\"type\": \"sky\", \"model\": \"cie_clear\", \"radiance\": [1, 1, "
            "1]}]}",
            "/lights/0/model", "unknown sky model \"cie_clear\""},
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
