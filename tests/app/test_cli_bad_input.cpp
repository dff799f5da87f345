// Bad input on the command line: a clear message naming the file and line, a non-zero exit,
// and no output directory or file left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kBad = std::string(RADIOSITY_DATA_DIR) + "/tests/bad/";

struct BadCase {
  std::string file;      // scene to load
  std::string location;  // "file:line:" expected in the message
  std::string phrase;
  std::string options = "";  // more arguments (--strict: an unreadable texture is an error)
};

// Readable names in test listings instead of gtest's byte dump.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.file; }

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, FailsClearlyAndWritesNothing) {
  const BadCase& c = GetParam();
  const auto out = testing::scratchPath(
      "bad_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + c.file);
  const auto result = testing::runRadiosity("solve " + kBad + c.file + " --out " + out.string() +
                                            " --rays 16 " + c.options);
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find("error: "), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find(c.location), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find(c.phrase), std::string::npos) << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out)) << "a failed run created " << out;
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadInput,
    ::testing::Values(
        BadCase{"nan_vertex.obj", "nan_vertex.obj:5:", "non-finite"},
        BadCase{"malformed_number.obj", "malformed_number.obj:5:", "malformed number"},
        BadCase{"missing_material.obj", "missing_material.obj:13:", "missing material"},
        BadCase{"missing_mtllib.obj", "missing_mtllib.obj:2:", "cannot open material library"},
        BadCase{"reflectance_above_one.obj",
                "reflectance_above_one.mtl:8:", "reflectance must be in [0, 1]"},
        BadCase{"negative_emission.obj",
                "negative_emission.mtl:4:", "emission must be non-negative"},
        BadCase{"no_emitter.obj", "no_emitter.obj", "no emitter"},
        BadCase{"bad_index.obj", "bad_index.obj:14:", "out of range"},
        BadCase{"short_face.obj", "short_face.obj:14:", "at least 3"},
        BadCase{"does_not_exist.obj", "does_not_exist.obj", "cannot open"},
        BadCase{"texture_missing.obj", "texture_missing.mtl:5:", "cannot open the texture file",
                "--strict"},
        BadCase{"texture_corrupt.obj", "texture_corrupt.mtl:5:", "corrupt.png", "--strict"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      std::string name = info.param.file.substr(0, info.param.file.find('.'));
      for (char& ch : name)
        if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

// Without --strict a texture that cannot be read is what Blender and engines make of it: a
// warning naming the MTL line, the material's own colour (Kd) instead, and the file listed in
// summary.json; the solve goes on and writes its outputs.
TEST(BadInput, AnUnreadableTextureFallsBackToItsMaterialsColourWithAWarning) {
  for (const std::string scene : {"texture_missing", "texture_corrupt"}) {
    const auto out = testing::scratchPath("texture_fallback_" + scene);
    const auto result = testing::runRadiosity("solve " + kBad + scene + ".obj --out " +
                                              out.string() + " --rays 16");
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    const std::string line = scene + ".mtl:5:";
    EXPECT_NE(result.stderrText.find(line), std::string::npos) << result.stderrText;
    EXPECT_NE(result.stderrText.find("using the material's own colour"), std::string::npos)
        << result.stderrText;
    std::ifstream in(out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    const nlohmann::json& fallbacks = summary["scene"]["texture_fallbacks"];
    ASSERT_EQ(fallbacks.size(), 1u) << fallbacks;
    EXPECT_NE(fallbacks[0].get<std::string>().find(line), std::string::npos) << fallbacks;
    std::filesystem::remove_all(out);
  }
}

// A scene in a format radiosity does not read (here PLY): named as such, exit 1, no output
// directory.
TEST(BadInput, UnsupportedSceneFormatIsNamedAndWritesNothing) {
  const auto dir = testing::scratchPath("unsupported_format");
  std::filesystem::create_directories(dir);
  const auto ply = dir / "x.ply";
  std::ofstream(ply, std::ios::binary) << "ply\nformat binary_little_endian 1.0\nend_header\n";
  const auto out = dir / "o";
  const auto result = testing::runRadiosity("solve " + ply.string() + " --out " + out.string());
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find(ply.string() + ": unsupported scene format (PLY)"),
            std::string::npos)
      << result.stderrText;
  EXPECT_NE(result.stderrText.find("radiosity reads OBJ (.obj)"), std::string::npos)
      << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out)) << "a failed run created " << out;
  std::filesystem::remove_all(dir);
}

// A binary glTF cut short after its header: the glTF reader names the file, exit 1, nothing
// written.
TEST(BadInput, TruncatedGlbIsAnInputErrorAndWritesNothing) {
  const auto dir = testing::scratchPath("truncated_glb");
  std::filesystem::create_directories(dir);
  const auto glb = dir / "x.glb";
  std::ofstream(glb, std::ios::binary)
      << std::string("glTF\x02\x00\x00\x00\x20\x00\x00\x00", 12) << "binary glTF bytes";
  const auto out = dir / "o";
  const auto result = testing::runRadiosity("solve " + glb.string() + " --out " + out.string());
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find(glb.string() + ": binary glTF: the first chunk is not a JSON"),
            std::string::npos)
      << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out)) << "a failed run created " << out;
  std::filesystem::remove_all(dir);
}

TEST(BadOptions, UnknownOptionIsAUsageError) {
  const auto out = testing::scratchPath("unknown_option");
  const auto result =
      testing::runRadiosity("solve " + kCornell + " --out " + out.string() + " --frobnicate 3");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.stderrText.find("frobnicate"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(BadOptions, UnknownSolverAndImpossibleValuesAreErrors) {
  const auto out = testing::scratchPath("bad_values");
  // Exit 2 where the option's own type or choices refuse the value (usage), 1 where the solve
  // options' check does (bad input); the message names the option either way.
  const struct {
    std::string arguments, option;
    int exitCode;
  } cases[] = {{"--solver magic", "--solver", 2},
               {"--rays 0", "--rays", 1},
               {"--tolerance -1", "--tolerance", 1},
               {"--max-area -2", "--max-area", 1},
               {"--bounces 3 --solver gauss-seidel", "--bounces", 1},
               {"--rays abc", "--rays", 2}};
  for (const auto& c : cases) {
    const auto result =
        testing::runRadiosity("solve " + kCornell + " --out " + out.string() + " " + c.arguments);
    EXPECT_EQ(result.exitCode, c.exitCode) << c.arguments << "\n" << result.stderrText;
    EXPECT_NE(result.stderrText.find(c.option), std::string::npos)
        << c.arguments << ": " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.arguments;
  }
}

TEST(BadOptions, OutputPathThatIsAFileFailsWithoutTouchingIt) {
  const auto out = testing::scratchPath("out_is_file");
  { std::ofstream(out) << "keep me\n"; }
  const auto result = testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                                            " --rays 16 --elements 50");
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find(out.string()), std::string::npos) << result.stderrText;
  std::ifstream in(out);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "keep me");
  std::filesystem::remove(out);
}

TEST(BadOptions, AbsurdElementCountIsRejectedBeforeAnyWork) {
  const auto out = testing::scratchPath("too_many_elements");
  const auto result =
      testing::runRadiosity("solve " + kCornell + " --out " + out.string() + " --max-area 1e-12");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.stderrText.find("--max-area"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(PartialOutput, AFileThatCannotBeWrittenLeavesNoneOfTheOthers) {
  // vertex_colors.ply cannot take its name (a directory is in the way): elements.csv and
  // summary.json, though complete, must not appear either.
  const auto out = testing::scratchPath("blocked_ply");
  std::filesystem::create_directories(out / "vertex_colors.ply");
  const auto result = testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                                            " --rays 16 --elements 50");
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out / "elements.csv"));
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
  for (const auto& entry : std::filesystem::directory_iterator(out))
    EXPECT_EQ(entry.path().filename(), "vertex_colors.ply") << "left behind: " << entry.path();
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace rad
