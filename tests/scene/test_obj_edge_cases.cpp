// OBJ/MTL syntax corners, written to a temporary directory: what is accepted, and where each
// error is reported.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

const char* const kSquareVertices =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

const char* const kMaterials =
    "newmtl lamp\n"
    "Kd 0 0 0\n"
    "Ke 1 2 3\n"
    "newmtl grey\n"
    "Kd 0.5 0.5 0.5\n";

class ObjEdgeCases : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("radiosity_scene_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
  }

  // Expects "<dir>/<file>:<line>: ...phrase..." from loading `obj`.
  void expectError(const std::string& obj, const std::string& file, int line,
                   const std::string& phrase) {
    try {
      loadObjScene((dir_ / obj).string());
      FAIL() << obj << " loaded without an error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      const std::string location = (dir_ / file).string() + ":" + std::to_string(line) + ": ";
      EXPECT_EQ(what.rfind(location, 0), 0u) << what;
      EXPECT_NE(what.find(phrase), std::string::npos) << what;
      EXPECT_EQ(e.line(), line);
    }
  }

  fs::path dir_;
};

TEST_F(ObjEdgeCases, AcceptsCrlfCommentsRelativeIndicesAndGroups) {
  write("m.mtl", "# header\r\nnewmtl lamp   # trailing comment\r\nKe 1 2 3\r\n");
  const std::string obj = write("s.obj",
                                "mtllib m.mtl\r\n"
                                "g first\r\n"
                                "v 0 0 0 # origin\r\n"
                                "v 1 0 0\r\n"
                                "v 1 1 0\r\n"
                                "vt 0 0\r\n"
                                "vn 0 0 1\r\n"
                                "usemtl lamp # the light\r\n"
                                "f -3/1/1 -2//1 -1/1 # relative\r\n"
                                "o second\r\n"
                                "s off\r\n"
                                "v 0 1 0\r\n"
                                "f 1 3 4\r\n");
  const Scene scene = loadObjScene(obj);
  ASSERT_EQ(scene.polygons.size(), 2u);
  EXPECT_EQ(scene.polygons[0].vertices, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(scene.polygons[0].sourceLine, 9);
  EXPECT_EQ(scene.polygons[1].sourceLine, 13);
  EXPECT_EQ(scene.polygons[1].material, 0);  // `usemtl` carries across `o`
  EXPECT_EQ(scene.materials[0].name, "lamp");
  EXPECT_EQ(scene.materials[0].sourceLine, 2);
  EXPECT_DOUBLE_EQ(scene.materials[0].emission.b, 3.0);
}

TEST_F(ObjEdgeCases, AcceptsOldMacLineEndsTabsByteOrderMarkAndAnEmptyLibrary) {
  write("empty.mtl", "");
  write("m.mtl", "\xEF\xBB\xBFnewmtl grey\rKd\t0.5 0.5 0.5");
  // A hexagon, groups between faces of one material, and no newline at the end.
  const std::string obj = write("s.obj",
                                "mtllib empty.mtl\rmtllib m.mtl\r"
                                "v 1 0 0\rv 0.5 0.8 0\rv -0.5 0.8 0\r"
                                "v -1 0 0\rv -0.5 -0.8 0\rv 0.5 -0.8 0\r"
                                "usemtl grey\rg a\rf\t1 2 3 4 5 6\rg b\rf 1 2 3");
  const Scene scene = loadObjScene(obj);
  ASSERT_EQ(scene.materials.size(), 1u);  // nothing from the empty library
  ASSERT_EQ(scene.polygons.size(), 2u);
  EXPECT_EQ(scene.polygons[0].vertices.size(), 6u);
  EXPECT_EQ(scene.polygons[0].sourceLine, 11);
  EXPECT_EQ(scene.polygons[1].sourceLine, 13);
  EXPECT_EQ(scene.polygons[1].material, 0);
  EXPECT_EQ(scene.materials[0].sourceLine, 1);
  EXPECT_DOUBLE_EQ(scene.materials[0].diffuse.g, 0.5);
}

TEST_F(ObjEdgeCases, SeveralLibrariesKeepDefinitionOrder) {
  write("a.mtl", "newmtl grey\nKd 0.5 0.5 0.5\n");
  write("b.mtl", "newmtl lamp\nKe 1 1 1\n");
  write("c.mtl", "newmtl mirror\nKs 0.9 0.9 0.9\nillum 3\n");
  const std::string obj = write("s.obj", std::string("mtllib a.mtl b.mtl\n") + kSquareVertices +
                                             "usemtl lamp\nf 1 2 3\nmtllib c.mtl a.mtl\n"
                                             "usemtl mirror\nf 1 3 4\nusemtl grey\nf 2 3 4\n");
  const Scene scene = loadObjScene(obj);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[0].name, "grey");
  EXPECT_EQ(scene.materials[1].name, "lamp");
  EXPECT_EQ(scene.materials[2].name, "mirror");
  EXPECT_NE(scene.materials[2].sourceFile.find("c.mtl"), std::string::npos);
  ASSERT_EQ(scene.polygons.size(), 3u);
  EXPECT_EQ(scene.polygons[0].material, 1);
  EXPECT_EQ(scene.polygons[1].material, 2);
  EXPECT_EQ(scene.polygons[2].material, 0);
  EXPECT_TRUE(scene.hasSpecular());
  EXPECT_EQ(scene.emitterCount(), 1);
}

TEST_F(ObjEdgeCases, IllumSelectsTheSurfaceKind) {
  write("m.mtl",
        "newmtl a\nillum 2\nnewmtl b\nillum 3\nnewmtl c\nillum 5\nnewmtl d\nillum 7\n"
        "Ni 1.5\nTf 1 1 1\nNs 10\n");
  const std::string obj =
      write("s.obj", std::string("mtllib m.mtl\n") + kSquareVertices + "usemtl a\nf 1 2 3\n");
  const Scene scene = loadObjScene(obj);
  ASSERT_EQ(scene.materials.size(), 4u);
  EXPECT_EQ(scene.materials[0].kind, SurfaceKind::Diffuse);
  EXPECT_EQ(scene.materials[1].kind, SurfaceKind::Mirror);
  EXPECT_EQ(scene.materials[2].kind, SurfaceKind::Mirror);
  EXPECT_EQ(scene.materials[3].kind, SurfaceKind::Dielectric);
  EXPECT_DOUBLE_EQ(scene.materials[3].ior, 1.5);
  EXPECT_DOUBLE_EQ(scene.materials[3].shininess, 10.0);
  EXPECT_FALSE(scene.hasSpecular());  // only material a is used
}

TEST_F(ObjEdgeCases, DuplicateMaterialNameUsesTheFirstDefinition) {
  write("m.mtl", "newmtl x\nKd 0.25 0.25 0.25\nnewmtl x\nKd 0.75 0.75 0.75\n");
  const std::string obj =
      write("s.obj", std::string("mtllib m.mtl\n") + kSquareVertices + "usemtl x\nf 1 2 3\n");
  const Scene scene = loadObjScene(obj);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_DOUBLE_EQ(scene.materials[scene.polygons[0].material].diffuse.r, 0.25);
}

TEST_F(ObjEdgeCases, DegenerateThresholdIsRelativeToTheScene) {
  // A sliver 1e-4 high in a 1e-3 wide scene is a real face; coincident positions are not.
  const std::string obj = write("s.obj",
                                "v 0 0 0\nv 0.001 0 0\nv 0.0005 0.0001 0\nv 0 0 0\n"
                                "f 1 2 3\nf 1 2 4\n");
  const Scene scene = loadObjScene(obj);
  EXPECT_EQ(scene.polygons.size(), 1u);
  EXPECT_EQ(scene.skippedDegenerateFaces, 1);
  EXPECT_TRUE(scene.usedDefaultMaterial);
}

TEST_F(ObjEdgeCases, MissingObjNamesThePath) {
  try {
    loadObjScene((dir_ / "nothing.obj").string());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "nothing.obj").string() + ": cannot open OBJ file");
  }
}

TEST_F(ObjEdgeCases, ObjErrorsCarryTheirLine) {
  const std::string head = std::string("mtllib m.mtl\n") + kSquareVertices + "usemtl grey\n";
  write("m.mtl", kMaterials);
  write("zero.obj", head + "f 0 1 2\n");
  expectError("zero.obj", "zero.obj", 7, "vertex index 0 is invalid");
  write("frac.obj", head + "f 1 2.5 3\n");
  expectError("frac.obj", "frac.obj", 7, "vertex index '2.5' is not an integer");
  write("neg.obj", head + "f 1 2 -5\n");
  expectError("neg.obj", "neg.obj", 7, "vertex index -5 is out of range (4 defined");
  write("later.obj", head + "f 1 2 5\nv 0 0 1\n");
  expectError("later.obj", "later.obj", 7, "vertex index 5 is out of range");
  write("vt.obj", head + "f 1/1 2/1 3/1\n");
  expectError("vt.obj", "vt.obj", 7, "texture coordinate index 1 is out of range");
  write("slash.obj", head + "f 1/ 2 3\n");
  expectError("slash.obj", "slash.obj", 7, "malformed vertex reference '1/'");
  write("hex.obj", "v 0x1p3 0 0\n");
  expectError("hex.obj", "hex.obj", 1, "malformed number '0x1p3'");
  write("inf.obj", "v 0 0 0\nv 1 -inf 0\n");
  expectError("inf.obj", "inf.obj", 2, "non-finite number '-inf'");
  write("huge.obj", "v 1e999 0 0\n");
  expectError("huge.obj", "huge.obj", 1, "non-finite number '1e999'");
  // strtod reads "0.e372702" as 0, tinyobjloader as 0 × pow(10, 372702) = NaN (a fuzzer find).
  write("nan.obj", head + "v 0.e372702 0 0\n");
  expectError("nan.obj", "nan.obj", 7,
              "number '0.e372702' in 'v' statement has an exponent beyond");
  write("tiny.obj", head + "vt 1e-400 0\n");
  expectError("tiny.obj", "tiny.obj", 7, "exponent beyond ±308");
  write("two.obj", "v 1 2\n");
  expectError("two.obj", "two.obj", 1, "'v' needs at least 3 numbers, found 2");
  write("early.obj", std::string("usemtl grey\nmtllib m.mtl\n"));
  expectError("early.obj", "early.obj", 1, "missing material 'grey' (no mtllib before this line)");
  write("spaces.obj", head + "usemtl my grey\n");
  expectError("spaces.obj", "spaces.obj", 7, "contains spaces");
  write("nolib.obj", "mtllib\n");
  expectError("nolib.obj", "nolib.obj", 1, "'mtllib' needs a file name");
}

// Exponents within a double's range, however written, are read as strtod reads them.
TEST_F(ObjEdgeCases, ExponentsWithinRangeAreAccepted) {
  write("m.mtl", kMaterials);
  const Scene scene = loadObjScene(
      write("e.obj",
            "mtllib m.mtl\nv 0 0 0\nv 1e+0000000 0 0\nv 1E0 10e-1 0\nv 0 0.01e+002 1e-308\n"
            "usemtl lamp\nf 1 2 3 4\n"));
  ASSERT_EQ(scene.positions.size(), 4u);
  EXPECT_EQ(scene.positions[1].x(), 1.0);
  EXPECT_EQ(scene.positions[2].y(), 1.0);
  EXPECT_EQ(scene.positions[3].y(), 1.0);
  EXPECT_GE(scene.positions[3].z(), 0.0);
  EXPECT_LT(scene.positions[3].z(), 1e-300);
}

TEST_F(ObjEdgeCases, TextureCoordinatesArePerFaceCorner) {
  write("m.mtl", kMaterials);
  write("uv.obj", std::string("mtllib m.mtl\n") + kSquareVertices +
                      "vt 0.25 0.5\nvt 0.75 0.5\nvt 0.75 1 0\nvt 0.1\n"
                      "usemtl lamp\nf 1/1 2/2 3/3\nf 1/-1 3/3 4/1\nf 1 3 4\nf 1/1 3 4/2\n");
  const Scene scene = loadObjScene((dir_ / "uv.obj").string());
  ASSERT_EQ(scene.polygons.size(), 4u);
  EXPECT_EQ(scene.polygonsWithUvs(), 2);
  auto expectUvs = [](const std::vector<Eigen::Vector2d>& got,
                      const std::vector<Eigen::Vector2d>& expected) {
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i)  // tinyobjloader's own number parser: within rounding
      EXPECT_LT((got[i] - expected[i]).cwiseAbs().maxCoeff(), 1e-12) << i;
  };
  expectUvs(scene.polygons[0].uvs, {{0.25, 0.5}, {0.75, 0.5}, {0.75, 1}});
  // A relative index, a reused coordinate, and `vt u` alone (v defaults to 0).
  expectUvs(scene.polygons[1].uvs, {{0.1, 0}, {0.75, 1}, {0.25, 0.5}});
  EXPECT_TRUE(scene.polygons[2].uvs.empty());
  EXPECT_TRUE(scene.polygons[3].uvs.empty());  // some corners only: no UVs for the face
}

TEST_F(ObjEdgeCases, MalformedTextureCoordinatesCarryTheirLine) {
  const std::string head = std::string("mtllib m.mtl\n") + kSquareVertices;
  write("m.mtl", kMaterials);
  write("word.obj", head + "vt 0.5 half\n");
  expectError("word.obj", "word.obj", 6, "malformed number 'half'");
  write("empty.obj", head + "vt\n");
  expectError("empty.obj", "empty.obj", 6, "'vt' needs at least 1 number");
  write("four.obj", head + "vt 0 0 0 0\n");
  expectError("four.obj", "four.obj", 6, "'vt' needs at most 3 numbers, found 4");
  write("nan.obj", head + "vt nan 0\n");
  expectError("nan.obj", "nan.obj", 6, "non-finite number 'nan'");
  write("range.obj", head + "vt 0 0\nusemtl grey\nf 1/1 2/2 3/1\n");
  expectError("range.obj", "range.obj", 8, "texture coordinate index 2 is out of range (1 defined");
}

// Kd 1 (what exporters write for white) is accepted as reflectance 1; only above 1 is an error.
TEST_F(ObjEdgeCases, ReflectanceOneIsAcceptedAboveOneIsNot) {
  write("s.obj", std::string("mtllib m.mtl\nusemtl a\n") + kSquareVertices + "f 1 2 3\n");
  write("m.mtl", "newmtl a\nKd 1 1 1\nKe 1 1 1\n");
  const Scene scene = loadObjScene((dir_ / "s.obj").string());
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].diffuse.minComponent(), 1.0);
  write("m.mtl", "newmtl a\nKd 1 1.0000001 1\n");
  expectError("s.obj", "m.mtl", 2, "reflectance must be in [0, 1]");
}

TEST_F(ObjEdgeCases, MtlErrorsCarryTheirLine) {
  const std::string obj = std::string("mtllib m.mtl\n") + kSquareVertices + "f 1 2 3\n";
  write("s.obj", obj);
  const auto check = [&](const std::string& mtl, int line, const std::string& phrase) {
    write("m.mtl", mtl);
    expectError("s.obj", "m.mtl", line, phrase);
  };
  check("newmtl a\nKd 0.5 0.5\n", 2, "'Kd' needs exactly 3 numbers, found 2");
  check("newmtl a\nKd 0.5 0.5 0.5 0.5\n", 2, "'Kd' needs exactly 3 numbers, found 4");
  check("newmtl a\nKd 0.5 -0.1 0.5\n", 2, "reflectance must be in [0, 1]");
  check("newmtl a\nKd 0.5 0.5 0.5\nKe 1 nan 1\n", 3, "non-finite number 'nan' in 'Ke'");
  check("newmtl a\nKs 1 1 x\n", 2, "malformed number 'x' in 'Ks'");
  check("newmtl a\nTf xyz 1 1 1\n", 2, "'Tf' needs exactly 3 numbers, found 4");
  check("newmtl a\nNi inf\n", 2, "non-finite number 'inf' in 'Ni'");
  check("newmtl a\nNs\n", 2, "'Ns' needs exactly 1 number, found 0");
  check("newmtl a\nillum 2.5\n", 2, "'illum' needs one non-negative integer, found '2.5'");
  check("Kd 0.5 0.5 0.5\nnewmtl a\n", 1, "'Kd' before any 'newmtl'");
  check("newmtl\n", 1, "'newmtl' needs a material name");
  check("newmtl my mat\n", 1, "contains spaces");
}

}  // namespace
}  // namespace rad
