// `radiosity render --method radiosity` keeps its solution in --out and reuses it when the same
// scene is rendered again with the same solve options: the reused image must be bit-identical to
// the one rendered from the fresh solve, other options must solve again, and a saved solution
// edited by hand must be refused with its file and line, leaving no render half-written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/output/image_io.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kScene = std::string(RADIOSITY_DATA_DIR) + "/tests/mirror_room.obj";
const std::string kOptions =
    " --width 12 --height 10 --spp 2 --gather 2 --elements 120 --rays 64 -q";

nlohmann::json report(const fs::path& dir) {
  std::ifstream in(dir / "render.json");
  return nlohmann::json::parse(in);
}

bool reused(const fs::path& dir) {
  return report(dir)["radiosity"]["reused_saved_solution"].get<bool>();
}

TEST(CliRenderReuse, SecondRenderReusesTheSolutionAndGivesTheSameImage) {
  const fs::path out = scratchPath("render_reuse");
  ASSERT_EQ(runRadiosity("render " + kScene + " --out " + out.string() + kOptions).exitCode, 0);
  EXPECT_FALSE(reused(out));
  ASSERT_TRUE(fs::exists(out / "solution.csv"));
  ASSERT_TRUE(fs::exists(out / "solution.json"));
  const ImageRgb fresh = readExr((out / "render.exr").string());

  const auto again = runRadiosity("render " + kScene + " --out " + out.string() + kOptions);
  ASSERT_EQ(again.exitCode, 0) << again.stderrText;
  EXPECT_TRUE(reused(out));
  EXPECT_EQ(report(out)["radiosity"]["form_factor_rays"].get<uint64_t>(), 0u);
  const ImageRgb second = readExr((out / "render.exr").string());
  ASSERT_EQ(second.pixels.size(), fresh.pixels.size());
  for (size_t p = 0; p < fresh.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(second.pixels[p][c], fresh.pixels[p][c]) << p;

  // Other solve options, or --fresh-solve, solve again.
  ASSERT_EQ(
      runRadiosity("render " + kScene + " --out " + out.string() + kOptions + " --seed 5").exitCode,
      0);
  EXPECT_FALSE(reused(out));
  ASSERT_EQ(runRadiosity("render " + kScene + " --out " + out.string() + kOptions +
                         " --seed 5 --fresh-solve")
                .exitCode,
            0);
  EXPECT_FALSE(reused(out));
  fs::remove_all(out);
}

TEST(CliRenderReuse, EditedSolutionIsRefusedWithFileAndLine) {
  const fs::path out = scratchPath("render_reuse_bad");
  ASSERT_EQ(runRadiosity("render " + kScene + " --out " + out.string() + kOptions).exitCode, 0);
  // Line 3 (the second element) loses a field.
  std::ifstream in(out / "solution.csv");
  std::stringstream edited;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    edited << (n == 3 ? line.substr(0, line.rfind(',')) : line) << "\n";
  in.close();
  std::ofstream(out / "solution.csv") << edited.str();
  fs::remove(out / "render.exr");
  fs::remove(out / "render.json");

  const auto r = runRadiosity("render " + kScene + " --out " + out.string() + kOptions);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find((out / "solution.csv").string() + ":3:"), std::string::npos)
      << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr"));
  EXPECT_FALSE(fs::exists(out / "render.json"));
  fs::remove_all(out);
}

// A member of solution.json of the wrong type (here the solver's name, a number) is an input
// error naming the file and the member, not an exception from the JSON library.
TEST(CliRenderReuse, MistypedSolutionJsonMemberIsRefusedWithFileAndPointer) {
  const fs::path out = scratchPath("render_reuse_mistyped");
  ASSERT_EQ(runRadiosity("render " + kScene + " --out " + out.string() + kOptions).exitCode, 0);
  for (const std::string member : {"solver", "converged", "elements_file"}) {
    SCOPED_TRACE(member);
    nlohmann::json meta;
    {
      std::ifstream in(out / "solution.json");
      meta = nlohmann::json::parse(in);
    }
    const nlohmann::json kept = meta[member];
    meta[member] = nlohmann::json::array({1});
    std::ofstream(out / "solution.json") << meta.dump();
    fs::remove(out / "render.exr");
    fs::remove(out / "render.json");
    const auto r = runRadiosity("render " + kScene + " --out " + out.string() + kOptions);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.stderrText.find((out / "solution.json").string() + ": /" + member),
              std::string::npos)
        << r.stderrText;
    EXPECT_FALSE(fs::exists(out / "render.exr"));
    EXPECT_FALSE(fs::exists(out / "render.json"));
    meta[member] = kept;
    std::ofstream(out / "solution.json") << meta.dump();
  }
  fs::remove_all(out);
}

}  // namespace
}  // namespace rad
