// `radiosity view` refuses an option the user gave that its input does not use: exit 1, a message
// "NAME is not used: WHY", and no screenshot. The refusals come before any window (no display
// needed).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

void expectRefused(const std::string& input, const std::string& options,
                   const std::string& message) {
  const fs::path shot = scratchPath("view_unused.png");
  const auto r = runRadiosity("view " + input + " --screenshot " + shot.string() + " " + options);
  EXPECT_EQ(r.exitCode, 1) << options << "\n" << r.stderrText;
  EXPECT_NE(r.stderrText.find("error: " + message), std::string::npos) << options << "\n"
                                                                       << r.stderrText;
  EXPECT_FALSE(fs::exists(shot)) << options;
}

TEST(ViewUnusedOptions, ASavedSolutionDirectoryRefusesSolveAndSolverOptions) {
  // The input is a directory: what it holds is never read, the options are refused first.
  const fs::path dir = scratchPath("view_unused_dir");
  fs::create_directories(dir);
  expectRefused(dir.string(), "--seed 3",
                "--seed is not used: a saved solution.vtp (view DIR) is shown as it was solved");
  expectRefused(dir.string(), "--sky 1 1 1", "--sky is not used: a saved solution.vtp");
  expectRefused(dir.string(), "--rays 64", "--rays is not used: a saved solution.vtp");
  expectRefused(dir.string(), "--rays-of 3",
                "--rays-of is not used: a saved solution.vtp has no form factors");
  expectRefused(dir.string(), "--stop-after 2",
                "--stop-after is not used: a saved solution.vtp has no solver to step");
  fs::remove_all(dir);
}

TEST(ViewUnusedOptions, ASceneRefusesWhatItsSolverAndOutputDoNotUse) {
  expectRefused(kCornell, "--elements 60 --solver hierarchical --stop-after 2",
                "--stop-after is not used: the hierarchical solve is not stepped live");
  expectRefused(kCornell, "--elements 60 --no-help",
                "--no-help is not used: --screenshot draws no key overlay");
}

}  // namespace
}  // namespace rad
