// `radiosity render --method bdpt | --paths | --bounces-separate` end to end, and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "radiosity/output/image_io.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kFurnace = std::string(RADIOSITY_DATA_DIR) + "/tests/furnace_box.obj";
const std::string kFurnaceView =
    " --position 0.5 0.45 0.3 --look-at 0.7 0.6 1 --vfov 100 --width 6 --height 5 -q";

void expectError(const std::string& arguments, const std::string& fragment) {
  const fs::path out = scratchPath("path_types_error");
  const auto r = runRadiosity("render " + kFurnace + " --out " + out.string() + kFurnaceView + " " +
                              arguments);
  EXPECT_EQ(r.exitCode, 1) << arguments << "\n" << r.stderrText;
  EXPECT_NE(r.stderrText.find(fragment), std::string::npos) << arguments << "\n" << r.stderrText;
  EXPECT_FALSE(fs::exists(out / "render.exr")) << arguments;
}

TEST(CliPathTypes, BadOptionsAreClearErrors) {
  expectError("--method path --paths 'LS+(D'", "--paths 'LS+(D': missing ')'");
  expectError("--method bdpt --paths LXE", "unknown symbol 'X' at position 2");
  expectError("--method radiosity --paths LDE", "--paths needs --method path or bdpt");
  expectError("--method path --bounces-separate -1", "--bounces-separate must be >= 0");
  expectError("--method path --paths LDE --bounces-separate 2", "cannot be combined");
  expectError("--method bdpt --mis cubic", "unknown --mis 'cubic'");
  expectError("--method path --mis balance", "--mis applies to --method bdpt only");
  expectError("--method bidirectional", "unknown --method 'bidirectional'");
  expectError("--method radiosity --bounces-separate 2 --solver gauss-seidel",
              "runs --solver jacobi");
}

// Jacobi radiosity in the furnace: B_k = (ρF)^k E with every row of F summing to 1 in a closed
// box, so term k is E ρ^k everywhere and its image (B_k/π, interpolated) is 0.5^k exactly up to
// float rounding (EXR stores 32-bit floats). The running sum of the terms is the --gather 0
// image of the K-bounce solution.
TEST(CliPathTypes, RadiosityBounceTermsInTheFurnace) {
  const fs::path out = scratchPath("bounces_radiosity");
  const auto r = runRadiosity("render " + kFurnace + " --out " + out.string() + kFurnaceView +
                              " --method radiosity --gather 0 --spp 1 --elements 60 --rays 32 "
                              "--bounces-separate 3");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const ImageRgb full = readExr((out / "render.exr").string());
  const ImageRgb sum = readExr((out / "bounce_sum_3.exr").string());
  for (int k = 0; k <= 3; ++k) {
    const ImageRgb term = readExr((out / ("bounce_" + std::to_string(k) + ".exr")).string());
    for (const Rgb& p : term.pixels)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], std::pow(0.5, k), 1e-6) << "term " << k;
    EXPECT_TRUE(fs::exists(out / ("bounce_" + std::to_string(k) + ".png")));
    EXPECT_TRUE(fs::exists(out / ("bounce_sum_" + std::to_string(k) + ".png")));
  }
  for (size_t p = 0; p < full.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum.pixels[p][c], full.pixels[p][c], 1e-6);
  std::ifstream in(out / "render.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["bounces_separate"]["max_bounce"], 3);
  fs::remove_all(out);
}

// The path tracer's bounce images: term 0 is the emitter seen directly, exactly Ke = 1; the
// running sums of the terms grow towards the full image and never pass it.
TEST(CliPathTypes, PathBounceImagesAreWrittenWithTheRest) {
  const fs::path out = scratchPath("bounces_path");
  const auto r = runRadiosity("render " + kFurnace + " --out " + out.string() + kFurnaceView +
                              " --method path --spp 4 --bounces-separate 2");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const ImageRgb full = readExr((out / "render.exr").string());
  const ImageRgb term0 = readExr((out / "bounce_0.exr").string());
  const ImageRgb sum2 = readExr((out / "bounce_sum_2.exr").string());
  for (size_t p = 0; p < full.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(term0.pixels[p][c], 1.0);
      EXPECT_LE(sum2.pixels[p][c], full.pixels[p][c] * (1 + 1e-6));
    }
  fs::remove_all(out);
}

TEST(CliPathTypes, BdptWithPathsReportsTheExpression) {
  const fs::path out = scratchPath("bdpt_paths");
  const auto r = runRadiosity("render " + kFurnace + " --out " + out.string() + kFurnaceView +
                              " --method bdpt --spp 2 --paths 'LD+E' --mis balance");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  std::ifstream in(out / "render.json");
  const auto report = nlohmann::json::parse(in);
  EXPECT_EQ(report["paths"], "LD+E");
  EXPECT_EQ(report["mis"], "balance");
  EXPECT_NE(report["integrator"].get<std::string>().find("balance"), std::string::npos);
  fs::remove_all(out);
}

}  // namespace
}  // namespace rad
