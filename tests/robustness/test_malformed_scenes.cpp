// Hostile OBJ/MTL files (issue 9): each gives a clear error naming the file (and line), a
// non-zero exit that is not a crash, and no output. The files are generated here, so each case
// says exactly what it tests.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

const std::string kMtl = "newmtl light\nKd 0.5 0.5 0.5\nKe 10 10 10\nnewmtl wall\nKd 0.7 0.6 0.5\n";
const std::string kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";  // lines 2-5 after "mtllib"

struct HostileCase {
  const char* name;
  std::function<std::string()> obj;  // scene.obj's content (scene.mtl holds kMtl)
  std::string location;              // expected in the message: "scene.obj:LINE:" or a file
  std::string phrase;
};

void PrintTo(const HostileCase& c, std::ostream* os) { *os << c.name; }

std::string hugePolygon() {
  // 10^6 vertices on a circle and one face using them all.
  constexpr int n = 1000000;
  std::string text = "mtllib scene.mtl\n";
  text.reserve(40u * n);
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  text += "usemtl light\nf";
  for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
  return text + "\n";
}

class HostileScene : public ::testing::TestWithParam<HostileCase> {};

TEST_P(HostileScene, ClearErrorNoCrashNoOutput) {
  const HostileCase& c = GetParam();
  const fs::path dir = testing::scratchPath(std::string("hostile_") + c.name);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.obj", std::ios::binary) << c.obj();
  std::ofstream(dir / "scene.mtl", std::ios::binary) << kMtl;
  const fs::path out = dir / "out";
  const auto result = testing::runRadiosity("solve " + (dir / "scene.obj").string() + " --out " +
                                            out.string() + " --rays 16 --elements 50");
  EXPECT_EQ(result.exitCode, 1) << "exit " << result.exitCode << " (-1: killed by a signal)\n"
                                << result.stderrText;
  EXPECT_NE(result.stderrText.find("error: "), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find(c.location), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find(c.phrase), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(out)) << "a failed run created " << out;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Files, HostileScene,
    ::testing::Values(
        HostileCase{"truncated_vertex", [] { return "mtllib scene.mtl\n" + kQuad + "v 0.5 0.\n"; },
                    "scene.obj:6:", "v"},
        HostileCase{"truncated_face_reference",
                    [] { return "mtllib scene.mtl\n" + kQuad + "usemtl light\nf 1 2 3/\n"; },
                    "scene.obj:7:", "malformed vertex reference"},
        HostileCase{"index_out_of_range",
                    [] { return "mtllib scene.mtl\n" + kQuad + "usemtl light\nf 1 2 5\n"; },
                    "scene.obj:7:", "out of range"},
        HostileCase{"negative_index_beyond_count",
                    [] { return "mtllib scene.mtl\n" + kQuad + "usemtl light\nf -1 -2 -5\n"; },
                    "scene.obj:7:", "out of range"},
        HostileCase{"two_vertex_face",
                    [] { return "mtllib scene.mtl\n" + kQuad + "usemtl light\nf 1 2\n"; },
                    "scene.obj:7:", "at least 3"},
        HostileCase{"one_vertex_face",
                    [] { return "mtllib scene.mtl\n" + kQuad + "usemtl light\nf 1\n"; },
                    "scene.obj:7:", "at least 3"},
        HostileCase{"million_vertex_polygon", hugePolygon, "scene.obj:1000003:", "vertices"},
        HostileCase{
            "non_utf8_material_name",
            [] { return "mtllib scene.mtl\n" + kQuad + "usemtl \xff\xfe\xc3\x28\nf 1 2 3\n"; },
            "scene.obj:6:", "missing material"},
        HostileCase{"non_utf8_binary_garbage",
                    [] {
                      return std::string("mtllib scene.mtl\n") + kQuad +
                             "v \x80\x81\x82 \xc0\xaf 1\n";
                    },
                    "scene.obj:6:", "v"},
        HostileCase{"usemtl_without_mtllib", [] { return kQuad + "usemtl light\nf 1 2 3\n"; },
                    "scene.obj:5:", "no mtllib"},
        HostileCase{"mtllib_is_a_directory",
                    [] { return "mtllib .\n" + kQuad + "usemtl light\nf 1 2 3\n"; },
                    "scene.obj:1:", "cannot open material library"},
        HostileCase{"mtllib_missing_file",
                    [] { return "mtllib nowhere.mtl\n" + kQuad + "usemtl light\nf 1 2 3\n"; },
                    "scene.obj:1:", "cannot open material library"},
        HostileCase{"huge_coordinates",
                    [] {
                      return "mtllib scene.mtl\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nusemtl "
                             "light\nf 1 2 3\n";
                    },
                    "scene.obj", "beyond"},
        HostileCase{
            "overflowing_coordinate",
            [] {
              return "mtllib scene.mtl\nv 1e999 0 0\nv 0 1 0\nv 0 0 1\nusemtl light\nf 1 2 3\n";
            },
            "scene.obj:2:", "v"},
        // A fuzzer find: strtod reads "0.e372702" as 0, tinyobjloader as NaN; the face using
        // that vertex had NaN area and the whole scene was refused without a line.
        HostileCase{"exponent_beyond_double",
                    [] {
                      return "mtllib scene.mtl\n" + kQuad +
                             "v 0.5 0.e372702 0\nusemtl light\nf 1 2 3 4\nusemtl wall\nf 1 2 5\n";
                    },
                    "scene.obj:6:", "exponent beyond"},
        HostileCase{"empty_file", [] { return std::string(); }, "scene.obj", "emitter"}),
    [](const ::testing::TestParamInfo<HostileCase>& info) { return std::string(info.param.name); });

TEST(HostileScene, MtlWithBinaryGarbageNamesTheMtlLine) {
  const fs::path dir = testing::scratchPath("hostile_mtl_garbage");
  fs::create_directories(dir);
  std::ofstream(dir / "scene.obj") << "mtllib scene.mtl\n" << kQuad << "usemtl light\nf 1 2 3\n";
  std::ofstream(dir / "scene.mtl", std::ios::binary)
      << "newmtl light\nKd 0.5 \xff\xfe 0.5\nKe 1 1 1\n";
  const auto result = testing::runRadiosity("solve " + (dir / "scene.obj").string() + " --out " +
                                            (dir / "out").string() + " --rays 16 --elements 50");
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find("scene.mtl:2:"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
