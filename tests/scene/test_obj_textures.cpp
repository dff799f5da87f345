// Textured OBJ materials: map_Kd, map_Ke and map_d read from the MTL (paths relative to the MTL's
// folder, Windows separators, options), the Kd 0 rule of Maya and 3ds Max, each image decoded
// once, cut-out alpha, and the errors for missing and corrupt images at the MTL line.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// An uncompressed TGA (type 2, rows bottom first), 24 or 32 bit: `texels` holds rows top first,
// 3 or 4 bytes each.
std::string tga(int w, int h, int channels, const std::vector<unsigned char>& texels) {
  std::string out = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  out += {static_cast<char>(w),
          0,
          static_cast<char>(h),
          0,
          static_cast<char>(8 * channels),
          static_cast<char>(channels == 4 ? 8 : 0)};
  for (int y = h - 1; y >= 0; --y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = &texels[(y * w + x) * channels];
      out += {static_cast<char>(p[2]), static_cast<char>(p[1]), static_cast<char>(p[0])};
      if (channels == 4) out += static_cast<char>(p[3]);
    }
  return out;
}

double srgb(unsigned char byte) {  // IEC 61966-2-1, written out
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

const char* const kQuad =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

class ObjTextures : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("radiosity_textures_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "models" / "maps");
    setLogLevel(LogLevel::Info);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }
  // The OBJ in the test folder, its MTL in models/ (textures are relative to the MTL, not the
  // OBJ), one textured quad per material named.
  std::string scene(const std::string& mtl, const std::vector<std::string>& materials) {
    write("models/scene.mtl", mtl);
    std::string obj = std::string("mtllib models/scene.mtl\n") + kQuad;
    for (const std::string& m : materials) obj += "usemtl " + m + "\nf 1/1 2/2 3/3 4/4\n";
    return write("scene.obj", obj);
  }
  std::string mtlPath() const { return (dir_ / "models" / "scene.mtl").string(); }

  fs::path dir_;
};

TEST_F(ObjTextures, MapKdIsRelativeToTheMtlAndSrgbDecoded) {
  write("models/maps/wood.tga", tga(1, 1, 3, {200, 100, 50}));
  // A Windows exporter's separator, and the texture factor Kd.
  const Scene s =
      loadObjScene(scene("newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd maps\\wood.tga\n", {"wood"}));
  ASSERT_EQ(s.textures.size(), 1u);
  const Material& m = s.materials[0];
  ASSERT_EQ(m.diffuseTexture, 0);
  EXPECT_EQ(m.diffuse.r, 0.5);  // Kd is kept: the texture multiplies it
  EXPECT_FALSE(m.hasCutouts());
  const Rgb texel = s.textures[0].colour({0.5, 0.5});
  EXPECT_NEAR(texel.r, srgb(200), 1e-6);
  EXPECT_NEAR(texel.g, srgb(100), 1e-6);
  EXPECT_NEAR(texel.b, srgb(50), 1e-6);
}

TEST_F(ObjTextures, KdZeroWithMapKdMeansTheTextureAloneAndIsSaidOncePerMaterial) {
  write("models/maps/t.tga", tga(1, 1, 3, {255, 255, 255}));
  ::testing::internal::CaptureStderr();
  const Scene s = loadObjScene(
      scene("newmtl a\nKd 0 0 0\nmap_Kd maps/t.tga\nnewmtl b\nKd 0 0 0\nmap_Kd maps/t.tga\n"
            "newmtl black\nKd 0 0 0\n",
            {"a", "b", "black", "a"}));
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.materials[0].diffuse.r, 1.0);
  EXPECT_EQ(s.materials[1].diffuse.g, 1.0);
  EXPECT_EQ(s.materials[2].diffuse.maxComponent(), 0.0);  // untextured black stays black
  const std::string phrase = "has Kd 0 0 0 and a map_Kd: using the texture alone";
  EXPECT_NE(log.find(mtlPath() + ":1: material 'a' " + phrase), std::string::npos) << log;
  EXPECT_NE(log.find(mtlPath() + ":4: material 'b' " + phrase), std::string::npos) << log;
  // Once per material, however many faces use it.
  EXPECT_EQ(log.find(phrase, log.find(phrase, log.find(phrase) + 1) + 1), std::string::npos);
}

TEST_F(ObjTextures, AnImageSharedByMaterialsIsDecodedOncePerUse) {
  write("models/maps/t.tga", tga(1, 1, 3, {128, 128, 128}));
  const Scene s = loadObjScene(
      scene("newmtl a\nKd 1 1 1\nmap_Kd maps/t.tga\n"
            "newmtl b\nKd 1 1 1\nmap_Kd ./maps/../maps/t.tga\nmap_Ke maps/t.tga\nKe 1 1 1\n"
            "newmtl c\nKd 1 1 1\nmap_d maps/t.tga\n",
            {"a", "b", "c"}));
  // Colour uses (map_Kd, map_Ke) share one sRGB decoding; the coverage use is linear: two.
  ASSERT_EQ(s.textures.size(), 2u);
  EXPECT_EQ(s.materials[0].diffuseTexture, s.materials[1].diffuseTexture);
  EXPECT_EQ(s.materials[1].emissionTexture, s.materials[0].diffuseTexture);
  const Texture& coverage = s.textures[s.materials[2].alphaTexture];
  EXPECT_NE(s.materials[2].alphaTexture, s.materials[0].diffuseTexture);
  // map_d without an alpha channel: its grey value, linear (128/255), is the coverage.
  EXPECT_NEAR(coverage.alpha({0.5, 0.5}), 128 / 255.0, 1e-6);
  EXPECT_TRUE(s.materials[2].hasCutouts());
}

TEST_F(ObjTextures, TransparentTexelsInMapKdMakeCutouts) {
  write("models/maps/leaf.tga", tga(2, 1, 4, {0, 200, 0, 255, 0, 200, 0, 0}));
  write("models/maps/opaque.tga", tga(1, 1, 4, {0, 200, 0, 255}));
  const Scene s = loadObjScene(
      scene("newmtl leaf\nKd 1 1 1\nmap_Kd maps/leaf.tga\nnewmtl solid\nKd 1 1 1\nmap_Kd "
            "maps/opaque.tga\n",
            {"leaf", "solid"}));
  EXPECT_TRUE(s.materials[0].alphaFromDiffuse);
  EXPECT_FALSE(s.materials[1].alphaFromDiffuse);
}

TEST_F(ObjTextures, MappingOptionsAreSkippedWithAWarningAndBumpOptionsSilently) {
  write("models/maps/t.tga", tga(1, 1, 3, {10, 20, 30}));
  ::testing::internal::CaptureStderr();
  const Scene s =
      loadObjScene(scene("newmtl a\nKd 1 1 1\nmap_Kd -s 2 2 1 -bm 0.5 -blendu on maps/t.tga\n"
                         "newmtl b\nKd 1 1 1\nmap_Kd -s 1 1 1 -o 0 0 maps/t.tga\n",
                         {"a", "b"}));
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(s.materials[0].diffuseTexture, s.materials[1].diffuseTexture);
  EXPECT_NE(log.find(mtlPath() + ":3: 'map_Kd' option '-s 2 2 1' is not supported"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find(":6:"), std::string::npos) << log;  // identity scale and offset: no warning
}

TEST_F(ObjTextures, FacesWithoutTextureCoordinatesUseTheFactorsWithAWarning) {
  write("models/maps/t.tga", tga(1, 1, 3, {10, 20, 30}));
  write("models/scene.mtl", "newmtl a\nKd 0.3 0.3 0.3\nmap_Kd maps/t.tga\n");
  const std::string obj = write("scene.obj", std::string("mtllib models/scene.mtl\n") + kQuad +
                                                 "usemtl a\nf 1/1 2/2 3/3\nf 1 3 4\n");
  ::testing::internal::CaptureStderr();
  const Scene s = loadObjScene(obj);
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(s.polygons[1].uvs.empty());
  EXPECT_NE(log.find(obj + ": 1 face(s) with a textured material have no texture coordinates "
                           "('vt') (line 12)"),
            std::string::npos)
      << log;
}

// Asked to use the material's colour (the command line's default), a missing map is a warning at
// its MTL line, no texture, the factors as written, and one fallback however many maps name it.
TEST_F(ObjTextures, AMissingTextureCanFallBackToTheMaterialsColour) {
  const std::string obj = scene(
      "newmtl a\nKd 0.25 0.5 0.75\nmap_Kd maps/absent.png\nnewmtl b\nKd 0.1 0.1 0.1\n"
      "map_Kd maps/absent.png\n",
      {"a", "b"});
  ::testing::internal::CaptureStderr();
  const Scene s = loadObjScene(obj, UnreadableTextures::UseMaterialColour);
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].diffuseTexture, -1);
  EXPECT_EQ(s.materials[1].diffuseTexture, -1);
  EXPECT_FALSE(s.materials[0].alphaFromDiffuse);
  EXPECT_DOUBLE_EQ(s.materials[0].diffuse[2], 0.75);
  EXPECT_TRUE(s.textures.empty());
  ASSERT_EQ(s.textureFallbacks.size(), 1u);
  EXPECT_NE(s.textureFallbacks[0].find(mtlPath() + ":3:"), std::string::npos)
      << s.textureFallbacks[0];
  EXPECT_NE(log.find(mtlPath() + ":3:"), std::string::npos) << log;
  EXPECT_NE(log.find("--strict"), std::string::npos) << log;
}

// Expects the InputError of loading `obj` to name the MTL file and the map_* line.
void expectErrorAt(const std::string& obj, const std::string& mtl, int line,
                   const std::string& phrase) {
  try {
    loadObjScene(obj);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), mtl);
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
  }
}

TEST_F(ObjTextures, AMissingTextureIsAnErrorAtTheMtlLine) {
  expectErrorAt(scene("newmtl a\nKd 1 1 1\nmap_Kd maps/absent.png\n", {"a"}), mtlPath(), 3,
                "cannot open the texture file");
}

TEST_F(ObjTextures, ACorruptPngIsAnErrorAtTheMtlLine) {
  // A PNG signature and then garbage.
  write("models/maps/bad.png", std::string("\x89PNG\r\n\x1a\n", 8) + "not really a png");
  expectErrorAt(scene("newmtl a\nKd 1 1 1\nKe 1 1 1\nmap_Ke maps/bad.png\n", {"a"}), mtlPath(), 4,
                "bad.png");
}

TEST_F(ObjTextures, MalformedMapStatementsAreErrorsAtTheirLine) {
  expectErrorAt(scene("newmtl a\nmap_Kd\n", {"a"}), mtlPath(), 2, "needs a file name");
  expectErrorAt(scene("newmtl a\nmap_Kd -s 2 2\n", {"a"}), mtlPath(), 2, "a file name after it");
  expectErrorAt(scene("newmtl a\nmap_Kd -warp 3 t.png\n", {"a"}), mtlPath(), 2,
                "unknown texture option '-warp'");
}

}  // namespace
}  // namespace rad
