// Two-sided surfaces on the command line: --two-sided and --two-sided-materials on the solve
// options (every command that loads a scene), each side counted in summary.json, and an unknown
// material named with the option, exit 1 and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// A grey quad facing down (lit by --sky only on its upper side, when that side exists).
fs::path writeDownwardQuad(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
                                     "usemtl grey\nf 1 2 3 4\n";
  std::ofstream(dir / "quad.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
  return dir / "quad.obj";
}

TEST(CliTwoSided, UnknownMaterialIsAnErrorThatNamesItExitsOneAndWritesNothing) {
  const fs::path dir = testing::scratchPath("two_sided_unknown");
  const fs::path scene = writeDownwardQuad(dir);
  const fs::path out = dir / "out";
  const auto result = testing::runRadiosity("solve " + scene.string() +
                                            " --sky 1 1 1 --two-sided-materials grey,wallpaper "
                                            "--out " +
                                            out.string());
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find("--two-sided-materials"), std::string::npos)
      << result.stderrText;
  EXPECT_NE(result.stderrText.find("'wallpaper'"), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find(scene.string()), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(out)) << "a failed run created " << out;
  fs::remove_all(dir);
}

TEST(CliTwoSided, SummaryCountsTheBackSides) {
  const fs::path dir = testing::scratchPath("two_sided_summary");
  const fs::path scene = writeDownwardQuad(dir);
  for (const std::string& flag :
       {std::string("--two-sided"), std::string("--two-sided-materials grey"), std::string()}) {
    const fs::path out = dir / "out";
    const auto result = testing::runRadiosity("solve " + scene.string() + " --sky 1 1 1 " + flag +
                                              " --elements 64 --rays 64 --out " + out.string());
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    std::ifstream in(out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in)["scene"];
    const bool twoSided = !flag.empty();
    EXPECT_EQ(summary["polygons"], twoSided ? 2 : 1) << flag;
    EXPECT_EQ(summary["back_side_polygons"], twoSided ? 1 : 0) << flag;
    // Each side is meshed alike (the copy is the same polygon reversed): half the elements.
    EXPECT_EQ(2 * summary["back_side_elements"].get<int>(),
              twoSided ? summary["elements"].get<int>() : 0)
        << flag;
    fs::remove_all(out);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
