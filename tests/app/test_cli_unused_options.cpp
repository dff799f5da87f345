// Every command refuses an option the user gave that its method or mode does not use: exit 1 (bad
// input), a message "NAME is not used: WHY" naming the option, and nothing written. The same
// options at their defaults, or given where they apply, still run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";
// Small enough that a run that wrongly goes ahead finishes in about a second.
const std::string kSmallSolve = " --elements 60 --rays 16 -q";
const std::string kSmall = kSmallSolve + " --width 8 --height 8 --spp 1";

struct Refusal {
  const char* name;       // test name
  std::string arguments;  // the command and its options; --out is added
  std::string message;    // the start of the error: the option and "is not used"
};

class CliUnusedOptions : public ::testing::TestWithParam<Refusal> {};

TEST_P(CliUnusedOptions, IsAnErrorNamingTheOptionAndWritesNothing) {
  const Refusal& c = GetParam();
  const fs::path out = scratchPath(std::string("unused_") + c.name);
  const auto r = runRadiosity(c.arguments + " --out " + out.string());
  EXPECT_EQ(r.exitCode, 1) << c.arguments << "\n" << r.stderrText;
  EXPECT_NE(r.stderrText.find("error: " + c.message), std::string::npos) << c.arguments << "\n"
                                                                         << r.stderrText;
  EXPECT_FALSE(fs::exists(out)) << c.arguments;
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(
    Commands, CliUnusedOptions,
    ::testing::Values(
        // solve: options of a solver, a form-factor method or a feature that is not chosen.
        Refusal{"solve_link_epsilon", "solve " + kCornell + kSmallSolve + " --link-epsilon 0.1",
                "--link-epsilon is not used: it sets the links of --solver hierarchical"},
        Refusal{"solve_probe_rays", "solve " + kCornell + kSmallSolve + " --probe-rays 16",
                "--probe-rays is not used: light probes are off without --probes"},
        // render: the final gather's options with a method that does not gather.
        Refusal{
            "render_path_light_rays",
            "render " + kCornell + " --width 8 --height 8 --spp 1 --method path --light-rays 16",
            "--light-rays is not used: --method path does not solve radiosity"},
        Refusal{"render_direct_gather",
                "render " + kCornell + " --width 8 --height 8 --spp 1 --method direct --gather 4",
                "--gather is not used: --method direct does not solve radiosity"},
        Refusal{"render_whitted_solution",
                "render " + kCornell +
                    " --width 8 --height 8 --spp 1 --method whitted --solution /nonexistent",
                "--solution is not used: --method whitted does not solve radiosity"},
        Refusal{"render_path_fresh_solve",
                "render " + kCornell + " --width 8 --height 8 --spp 1 --method path --fresh-solve",
                "--fresh-solve is not used: --method path does not solve radiosity"},
        Refusal{"render_path_mis",
                "render " + kCornell + " --width 8 --height 8 --spp 1 --method path --mis power",
                "--mis is not used: --mis applies to --method bdpt only"},
        // The camera's thin-lens focus on a pinhole camera (the Cornell box's has lens radius 0).
        Refusal{"render_pinhole_focus",
                "render " + kCornell +
                    " --width 8 --height 8 --spp 1 --method direct "
                    "--focus-distance 2",
                "--focus-distance is not used: the camera is a pinhole"},
        // compare: --gather when none of the methods gathers.
        Refusal{"compare_gather",
                "compare " + kCornell +
                    " --width 8 --height 8 --spp 1 --methods direct,path "
                    "--gather 4",
                "--gather is not used: none of the --methods solves radiosity"},
        Refusal{"compare_rays",
                "compare " + kCornell + " --width 8 --height 8 --spp 1 --methods whitted --rays 8",
                "--rays is not used: none of the --methods solves radiosity"},
        // bake: what only the lightmap reads, with --no-lightmap (vertex colours only).
        Refusal{"bake_no_lightmap_gather",
                "bake " + kCornell + " --elements 60 --rays 16 -q --no-lightmap --gather 4",
                "--gather is not used: --no-lightmap bakes vertex colours only"},
        Refusal{"bake_no_lightmap_light_rays",
                "bake " + kCornell + " --elements 60 --rays 16 -q --no-lightmap --light-rays 4",
                "--light-rays is not used: --no-lightmap bakes vertex colours only"},
        Refusal{"bake_no_lightmap_texel_size",
                "bake " + kCornell + " --elements 60 --rays 16 -q --no-lightmap --texel-size 0.1",
                "--texel-size is not used: --no-lightmap bakes vertex colours only"},
        Refusal{"bake_no_lightmap_content",
                "bake " + kCornell +
                    " --elements 60 --rays 16 -q --vertex-colors-only --lightmap-content "
                    "irradiance",
                "--lightmap-content is not used: --no-lightmap bakes vertex colours only"},
        Refusal{"bake_analytic_rays",
                "bake " + kCornell + " --elements 60 -q --form-factors analytic --rays 16",
                "--rays is not used: --form-factors analytic"}),
    [](const ::testing::TestParamInfo<Refusal>& info) { return std::string(info.param.name); });

// relight and update take only what every kept solve uses (the solver, its stopping rule, the
// threads): the solve's other options are no options of theirs, a usage error (exit 2).
TEST(CliUnusedOptions, RelightAndUpdateTakeNoSolveOptionsOfTheirOwn) {
  const fs::path kept = scratchPath("unused_kept");
  for (const std::string command : {"relight", "update"})
    for (const std::string option : {"--rays 64", "--seed 2", "--gather 4"}) {
      const auto r = runRadiosity(command + " " + kept.string() + " " + option);
      EXPECT_EQ(r.exitCode, 2) << command << " " << option << "\n" << r.stderrText;
      EXPECT_NE(r.stderrText.find(option.substr(0, option.find(' '))), std::string::npos)
          << r.stderrText;
    }
  EXPECT_FALSE(fs::exists(kept));
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The gather's options where they apply, and a refused option's default (not given), still run.
TEST(CliUnusedOptions, OptionsWhereTheyApplyStillRun) {
  const fs::path out = scratchPath("unused_valid_render");
  auto r = runRadiosity("render " + kCornell + " --out " + out.string() + kSmall +
                        " --method radiosity --gather 0 --light-rays 2");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const nlohmann::json report = readJson(out / "render.json");
  EXPECT_EQ(report["gather_rays"], 0);
  EXPECT_EQ(report["light_rays"], 2);
  fs::remove_all(out);

  // --method path reads none of the gather's options: their defaults are no error.
  r = runRadiosity("render " + kCornell + " --out " + out.string() +
                   " --width 8 --height 8 --spp 1 --method path --seed 3 -q");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  EXPECT_EQ(readJson(out / "render.json")["light_rays"], 0);
  fs::remove_all(out);

  r = runRadiosity("compare " + kCornell + " --out " + out.string() + kSmall +
                   " --methods direct,radiosity --gather 2");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  EXPECT_TRUE(fs::exists(out / "compare.png"));
  fs::remove_all(out);

  r = runRadiosity("bake " + kCornell + " --out " + out.string() +
                   " --elements 60 --rays 16 -q --lightmap-size 32 --gather 1 --light-rays 2");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  EXPECT_EQ(readJson(out / "bake.json")["lightmap"]["light_rays"], 2);
  fs::remove_all(out);
}

}  // namespace
}  // namespace rad
