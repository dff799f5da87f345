// The relight override file reader: materials by name to their index, lights by index and by
// group (the index winning), and every error naming the file, the line and the JSON pointer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/scene/scene_overrides.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() /
                       ("radiosity_overrides_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Compared whole, so a failure shows both triples at the caller's line.
using Triple = std::array<double, 3>;
Triple rgb(const Rgb& c) { return {c.r, c.g, c.b}; }

const std::vector<std::string> kMaterials = {"white", "red", "lamp", "green"};
const std::vector<std::string> kGroups = {"lamp", "point1", "lamp", "sky"};

TEST(SceneOverrides, ReadsMaterialsByNameAndLightsByIndexAndGroup) {
  const fs::path dir = scratch("valid");
  const std::string path = (dir / "over.json").string();
  std::ofstream(path) << R"({"comment": "evening", "materials": {
    "red": {"diffuse": [0.5, 0.25, 0], "emission": [0, 0, 1], "comment": "paint"},
    "lamp": {"emission": [10, 8, 6]}},
  "lights": {
    "lamp": {"scale": [2, 3, 4]},
    "2": {"scale": 0.5, "comment": "the index wins over the group"},
    "1": {"scale": 0}}})";
  const SceneOverrides o = loadSceneOverrides(path, kMaterials, kGroups);
  ASSERT_EQ(o.materials.size(), 2u);
  ASSERT_EQ(o.materials.count(1), 1u);
  ASSERT_TRUE(o.materials.at(1).diffuse && o.materials.at(1).emission);
  EXPECT_EQ(rgb(*o.materials.at(1).diffuse), (Triple{0.5, 0.25, 0}));
  EXPECT_EQ(rgb(*o.materials.at(1).emission), (Triple{0, 0, 1}));
  ASSERT_EQ(o.materials.count(2), 1u);
  EXPECT_FALSE(o.materials.at(2).diffuse);
  ASSERT_TRUE(o.materials.at(2).emission);
  EXPECT_EQ(rgb(*o.materials.at(2).emission), (Triple{10, 8, 6}));
  ASSERT_EQ(o.lightScale.size(), kGroups.size());
  EXPECT_EQ(rgb(o.lightScale[0]), (Triple{2, 3, 4}));        // by its group
  EXPECT_EQ(rgb(o.lightScale[1]), (Triple{0, 0, 0}));        // by its index, a scalar
  EXPECT_EQ(rgb(o.lightScale[2]), (Triple{0.5, 0.5, 0.5}));  // its index wins over its group
  EXPECT_EQ(rgb(o.lightScale[3]), (Triple{1, 1, 1}));        // not named: unchanged
  fs::remove_all(dir);
}

TEST(SceneOverrides, AnEmptyFileChangesNothingAndAGroupOrASharedNameReachesEachMember) {
  const fs::path dir = scratch("empty");
  const std::string path = (dir / "over.json").string();
  std::ofstream(path) << "{}";
  const SceneOverrides none = loadSceneOverrides(path, kMaterials, kGroups);
  EXPECT_TRUE(none.materials.empty());
  ASSERT_EQ(none.lightScale.size(), kGroups.size());
  for (const Rgb& s : none.lightScale) EXPECT_EQ(rgb(s), (Triple{1, 1, 1}));
  std::ofstream(path) << R"({"lights": {"lamp": {"scale": 3}}})";
  const SceneOverrides group = loadSceneOverrides(path, kMaterials, kGroups);
  EXPECT_EQ(rgb(group.lightScale[0]), (Triple{3, 3, 3}));  // a group scales each of its lights
  EXPECT_EQ(rgb(group.lightScale[1]), (Triple{1, 1, 1}));
  EXPECT_EQ(rgb(group.lightScale[2]), (Triple{3, 3, 3}));
  std::ofstream(path) << R"({"materials": {"a": {"diffuse": [1, 1, 1]}}})";
  const SceneOverrides shared = loadSceneOverrides(path, {"a", "b", "a"}, {});
  EXPECT_EQ(shared.materials.size(), 2u);
  EXPECT_EQ(shared.materials.count(0) + shared.materials.count(2), 2u);
  EXPECT_TRUE(shared.lightScale.empty());
  fs::remove_all(dir);
}

struct BadCase {
  const char* text;     // the file, over several lines
  int line;             // the line of the bad value
  const char* pointer;  // its JSON pointer, as the message must name it
  const char* message;  // a part of the message
};

TEST(SceneOverrides, ErrorsNameTheFileLineAndPointer) {
  const fs::path dir = scratch("errors");
  const std::string path = (dir / "over.json").string();
  const BadCase cases[] = {
      {"\n[1, 2]", 2, "", "one JSON object"},
      {"{\"materials\": {},\n \"light\": {}}", 2, "/light", "known: materials, lights, comment"},
      {"{\n\"materials\":\n [1]}", 3, "/materials", "must be a JSON object"},
      {"{\"materials\": {},\n\"lights\": \"all\"}", 2, "/lights", "must be a JSON object"},
      {"{\"materials\": {\n \"blue\": {\"diffuse\": [0, 0, 1]}}}", 2, "/materials/blue",
       "materials: white, red, lamp, green"},
      {"{\"materials\": {\n \"a/b~\": {}}}", 2, "/materials/a~1b~0", "no material named 'a/b~'"},
      {"{\"materials\": {\n \"red\":\n  3}}", 3, "/materials/red", "must be a JSON object"},
      {"{\"materials\": {\"red\": {\n \"Kd\": [1, 0, 0]}}}", 2, "/materials/red/Kd",
       "known: diffuse, emission, comment"},
      {"{\"materials\": {\n\"red\": {\"comment\": \"x\"}}}", 2, "/materials/red",
       "neither \"diffuse\" nor \"emission\""},
      {"{\"materials\": {\"red\": {\n\"diffuse\": [1, 0]}}}", 2, "/materials/red/diffuse",
       "array of 3 numbers"},
      {"{\"materials\": {\"red\": {\n\"diffuse\": [1, 0, \"0\"]}}}", 2, "/materials/red/diffuse",
       "array of 3 numbers"},
      {"{\"materials\": {\"red\": {\"emission\": [1, 1, 1],\n\"diffuse\": [1.5, 0, 0]}}}", 2,
       "/materials/red/diffuse", "each channel must be in [0, 1]"},
      {"{\"materials\": {\"red\": {\"diffuse\": [1, 1, 1],\n\"emission\": [1, -1, 0]}}}", 2,
       "/materials/red/emission", "must not be negative"},
      {"{\"lights\": {\n\"4\": {\"scale\": 1}}}", 2, "/lights/4",
       "no light with index 4 (the scene has 4 lights)"},
      {"{\"lights\": {\n\"lmap\": {\"scale\": 1}}}", 2, "/lights/lmap",
       "no light or light group named 'lmap' (groups: lamp, point1, sky)"},
      {"{\"lights\": {\n\"01\": {\"scale\": 1}}}", 2, "/lights/01", "leading zeros"},
      {"{\"lights\": {\n\"lamp\": [2]}}", 2, "/lights/lamp", "must be a JSON object"},
      {"{\"lights\": {\"lamp\": {\"scale\": 1,\n\"intensity\": 2}}}", 2, "/lights/lamp/intensity",
       "known: scale, comment"},
      {"{\"lights\": {\n\"0\": {\"comment\": \"off\"}}}", 2, "/lights/0", "missing key \"scale\""},
      {"{\"lights\": {\"0\": {\n\"scale\": -1}}}", 2, "/lights/0/scale", "must not be negative"},
      {"{\"lights\": {\"0\": {\n\"scale\": [1, 1, -0.5]}}}", 2, "/lights/0/scale",
       "must not be negative"},
      {"{\"lights\": {\"0\": {\n\"scale\": \"2\"}}}", 2, "/lights/0/scale",
       "a number or an array of 3 numbers"},
  };
  for (const BadCase& c : cases) {
    std::ofstream(path) << c.text;
    try {
      loadSceneOverrides(path, kMaterials, kGroups);
      ADD_FAILURE() << "accepted " << c.text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.file(), path) << c.text;
      EXPECT_EQ(e.line(), c.line) << what;
      EXPECT_NE(what.find(path + ":" + std::to_string(c.line) + ": " + c.pointer),
                std::string::npos)
          << what;
      EXPECT_NE(what.find(c.message), std::string::npos) << what;
    }
  }
  fs::remove_all(dir);
}

TEST(SceneOverrides, AMissingOrMalformedFileIsAnInputError) {
  const fs::path dir = scratch("malformed");
  const std::string path = (dir / "over.json").string();
  EXPECT_THROW(loadSceneOverrides(path, kMaterials, kGroups), InputError);
  std::ofstream(path) << "{\"lights\": {\n\"0\": {\"scale\": }}}";
  try {
    loadSceneOverrides(path, kMaterials, kGroups);
    ADD_FAILURE() << "accepted malformed JSON";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 2);
  }
  fs::remove_all(dir);
}

TEST(SceneOverrides, ListsAtMostTwentyNames) {
  const fs::path dir = scratch("list");
  const std::string path = (dir / "over.json").string();
  std::vector<std::string> names;
  for (int i = 0; i < 30; ++i) names.push_back("m" + std::to_string(i));
  std::ofstream(path) << R"({"materials": {"m30": {"diffuse": [0, 0, 0]}}})";
  try {
    loadSceneOverrides(path, names, {});
    ADD_FAILURE() << "accepted an unknown material";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("m19, …"), std::string::npos) << what;
    EXPECT_EQ(what.find("m20"), std::string::npos) << what;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
