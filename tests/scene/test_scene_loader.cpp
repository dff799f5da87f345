// loadScene: the scene format by extension and content; OBJ and glTF are read, PLY is not.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name, const std::string& bytes) {
  const fs::path dir = fs::temp_directory_path() / "radiosity_scene_loader";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The message of the InputError loadScene throws for `path` ("" when it loads).
std::string errorOf(const fs::path& path) {
  try {
    loadScene(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The first bytes of a binary glTF: magic, version 2, length, then the JSON chunk's header.
const std::string kGlb = std::string("glTF\x02\x00\x00\x00\x40\x00\x00\x00", 12) +
                         std::string("\x14\x00\x00\x00JSON", 8) +
                         "{\"asset\":{\"version\":\"2.0\"}}";
const std::string kPly = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nend_header\n";

TEST(SceneLoader, BinaryGltfAndGltfJsonAreReadByTheGltfLoader) {
  // A complete .glb: header, then a JSON chunk padded with spaces to a multiple of 4 bytes.
  std::string json = "{\"asset\":{\"version\":\"2.0\"}}";
  while (json.size() % 4) json += ' ';
  std::string glb = "glTF";
  for (std::uint32_t word : {2u, static_cast<std::uint32_t>(20 + json.size()),
                             static_cast<std::uint32_t>(json.size()), 0x4E4F534Au})
    for (int i = 0; i < 4; ++i) glb += static_cast<char>((word >> (8 * i)) & 0xFF);
  glb += json;
  EXPECT_EQ(errorOf(scratch("empty.glb", glb)), "");
  EXPECT_EQ(errorOf(scratch("empty.gltf", json)), "");
  // The loader's own errors come through, naming the file.
  const fs::path bad =
      scratch("bad_version.glb", kGlb.substr(0, 4) + std::string("\x01\0\0\0", 4) + kGlb.substr(8));
  EXPECT_NE(errorOf(bad).find("bad_version.glb: binary glTF version 1"), std::string::npos)
      << errorOf(bad);
  EXPECT_NE(readableSceneFormats().find("binary glTF (.glb), glTF (.gltf)"), std::string::npos);
}

TEST(SceneLoader, PlyIsUnsupported) {
  const fs::path ply = scratch("scene.ply", kPly);
  const std::string what = errorOf(ply);
  EXPECT_EQ(what.rfind(ply.string() + ": unsupported scene format (PLY)", 0), 0u) << what;
  EXPECT_NE(what.find("radiosity reads OBJ (.obj)"), std::string::npos) << what;
}

TEST(SceneLoader, UnknownOrMissingExtensionIsUnsupported) {
  std::string what = errorOf(scratch("scene.fbx", "Kaydara FBX Binary  \0"));
  EXPECT_NE(what.find("unsupported scene format (extension '.fbx')"), std::string::npos) << what;
  EXPECT_NE(what.find("radiosity reads OBJ (.obj)"), std::string::npos) << what;
  what = errorOf(scratch("scene", "v 0 0 0\n"));
  EXPECT_NE(what.find("unsupported scene format (no file extension)"), std::string::npos) << what;
  // The content is named where it is recognised.
  what = errorOf(scratch("scene.bin", kGlb));
  EXPECT_NE(what.find("unsupported scene format (binary glTF content, extension '.bin')"),
            std::string::npos)
      << what;
}

TEST(SceneLoader, ObjHoldingAnotherFormatSaysWhatItHolds) {
  std::string what = errorOf(scratch("renamed.obj", kGlb));
  EXPECT_NE(what.find("renamed.obj: unsupported scene format (binary glTF content in a .obj file)"),
            std::string::npos)
      << what;
  what = errorOf(scratch("renamed_ply.obj", kPly));
  EXPECT_NE(what.find("unsupported scene format (PLY content in a .obj file)"), std::string::npos)
      << what;
  what = errorOf(scratch("renamed_json.obj", "  {\"asset\": {}}"));
  EXPECT_NE(what.find("unsupported scene format (JSON content in a .obj file)"), std::string::npos)
      << what;
  // A .glb without the magic is not taken for anything else.
  what = errorOf(scratch("text.glb", "v 0 0 0\n"));
  EXPECT_NE(what.find("unsupported scene format (binary glTF by its extension"), std::string::npos)
      << what;
}

TEST(SceneLoader, MissingFileCannotBeOpened) {
  const std::string what = errorOf("/nonexistent/radiosity/scene.glb");
  EXPECT_NE(what.find("/nonexistent/radiosity/scene.glb: cannot open scene file"),
            std::string::npos)
      << what;
  EXPECT_NE(errorOf("/nonexistent/radiosity/scene.obj").find("cannot open"), std::string::npos);
}

TEST(SceneLoader, ObjStillLoadsWhateverTheCaseOfItsExtension) {
  const Scene scene = loadScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj");
  EXPECT_GT(scene.polygons.size(), 0u);
  EXPECT_GT(scene.emitterCount(), 0);
  const fs::path upper = scratch("TRIANGLE.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(loadScene(upper.string()).polygons.size(), 1u);
}

}  // namespace
}  // namespace rad
