// Solve options that the chosen method does not use are errors naming the option; every command
// that solves shares solve's defaults and reuses the solution `solve` wrote (--solution DIR).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CliOptions, RaysWithAnalyticFormFactorsIsAnErrorNamingRays) {
  const fs::path out = scratchPath("unused_rays");
  const auto r = runRadiosity("solve " + kCornell + " --form-factors analytic --rays 64 --out " +
                              out.string());
  EXPECT_EQ(r.exitCode, 1) << r.stderrText;
  EXPECT_NE(r.stderrText.find("--rays is not used"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliOptions, SolveOptionsWithAMethodThatDoesNotSolveAreErrors) {
  const fs::path out = scratchPath("unused_render");
  const auto r = runRadiosity("render " + kCornell + " --method path --elements 100 --out " +
                              out.string() + " --width 8 --height 8 --spp 1");
  EXPECT_EQ(r.exitCode, 1) << r.stderrText;
  EXPECT_NE(r.stderrText.find("--elements is not used: --method path does not solve"),
            std::string::npos)
      << r.stderrText;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliOptions, RenderAndBakeReuseTheSolutionSolveWrote) {
  const fs::path solved = scratchPath("reuse_solve");
  const std::string options = " --elements 150 --rays 64 -q";
  ASSERT_EQ(runRadiosity("solve " + kCornell + " --out " + solved.string() + options).exitCode, 0);
  ASSERT_TRUE(fs::exists(solved / "solution.json"));

  const fs::path rendered = scratchPath("reuse_render");
  const auto render =
      runRadiosity("render " + kCornell + " --out " + rendered.string() + " --solution " +
                   solved.string() + options + " --width 8 --height 8 --spp 1");
  ASSERT_EQ(render.exitCode, 0) << render.stderrText;
  const nlohmann::json report = readJson(rendered / "render.json");
  EXPECT_TRUE(report["radiosity"]["reused_saved_solution"].get<bool>());
  EXPECT_EQ(report["radiosity"]["form_factor_rays"].get<uint64_t>(), 0u);
  // The solve's element count, read back from its own summary (not from this command).
  EXPECT_EQ(report["radiosity"]["elements"],
            readJson(solved / "summary.json")["scene"]["elements"]);

  const fs::path baked = scratchPath("reuse_bake");
  const auto bake = runRadiosity("bake " + kCornell + " --out " + baked.string() + " --solution " +
                                 solved.string() + options + " --no-lightmap");
  ASSERT_EQ(bake.exitCode, 0) << bake.stderrText;
  EXPECT_TRUE(readJson(baked / "bake.json")["reused_saved_solution"].get<bool>());

  // Without --solution, bake reuses a matching solution in its own --out, as render does.
  const auto inPlace =
      runRadiosity("bake " + kCornell + " --out " + solved.string() + options + " --no-lightmap");
  ASSERT_EQ(inPlace.exitCode, 0) << inPlace.stderrText;
  EXPECT_TRUE(readJson(solved / "bake.json")["reused_saved_solution"].get<bool>());

  // Other solve options than the saved solution's: an error naming the directory, nothing written.
  const fs::path other = scratchPath("reuse_other");
  const auto mismatch = runRadiosity("bake " + kCornell + " --out " + other.string() +
                                     " --solution " + solved.string() + " --elements 90 --rays 64");
  EXPECT_EQ(mismatch.exitCode, 1) << mismatch.stderrText;
  EXPECT_NE(mismatch.stderrText.find(solved.string() + ": no solution to reuse"), std::string::npos)
      << mismatch.stderrText;
  EXPECT_FALSE(fs::exists(other));
  for (const fs::path& dir : {solved, rendered, baked}) fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
