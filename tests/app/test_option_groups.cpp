// The option groups of app/options/ parsed in-process: an option counts as given only when it is
// on the command line (a default never does), refusals name the option, each group refuses only
// what its mode does not read, and the choice lists come from the enums' tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "radiosity/app/options/camera_options.h"
#include "radiosity/app/options/exposure_option.h"
#include "radiosity/app/options/gather_options.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/core/errors.h"
#include "radiosity/pipeline/thread_limit.h"

namespace rad {
namespace {

// Parses `arguments` (after the program name) into `command`.
void parse(CLI::App& command, std::vector<std::string> arguments) {
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last to first
  command.parse(arguments);
}

// The InputError's message, or "" when `f` throws none.
template <class F>
std::string inputError(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionGroups, ASolveOptionCountsOnlyWhenGiven) {
  CLI::App command;
  SolveOptions options;
  addSolveOptions(command, options);
  parse(command, {"--seed", "7"});
  EXPECT_TRUE(wasGiven(command, "--seed"));
  EXPECT_FALSE(wasGiven(command, "--rays"));    // bound, at its default
  EXPECT_FALSE(wasGiven(command, "--gather"));  // not bound at all
  // A method that does not solve keeps --seed; the solve's defaults are no error.
  EXPECT_EQ(inputError([&] { finishWithoutSolve(command, options, "no solve here"); }), "");
  // view DIR reads nothing of the group, --seed included.
  EXPECT_EQ(inputError([&] { refuseAllSolveOptions(command, "a saved solution"); }),
            "--seed is not used: a saved solution");
}

TEST(OptionGroups, AMethodThatDoesNotSolveRefusesTheSolveOptionsButNotTheSceneInput) {
  CLI::App command;
  SolveOptions options;
  addSolveOptions(command, options);
  parse(command, {"--sky", "1", "1", "1", "--threads", "2", "--tolerance", "1e-3"});
  EXPECT_EQ(inputError([&] { finishWithoutSolve(command, options, "--method path"); }),
            "--tolerance is not used: --method path");
  CLI::App sceneOnly;
  SolveOptions other;
  addSolveOptions(sceneOnly, other);
  parse(sceneOnly, {"--sky", "1", "1", "1", "--threads", "2"});
  EXPECT_EQ(inputError([&] { finishWithoutSolve(sceneOnly, other, "--method path"); }), "");
  EXPECT_EQ(inputError([&] { refuseAllSolveOptions(sceneOnly, "a saved solution"); }),
            "--sky is not used: a saved solution");
}

TEST(OptionGroups, ChoicesComeFromTheEnumsTables) {
  CLI::App command;
  SolveOptions options;
  addSolveOptions(command, options);
  const std::string help = command.help();
  for (const std::string& name : tableNames(solverKindTable()))
    EXPECT_NE(help.find(name), std::string::npos) << name << " missing from: " << help;
  parse(command, {"--solver", "gauss-seidel", "--form-factors", "analytic"});
  EXPECT_EQ(options.solver, SolverKind::GaussSeidel);
  EXPECT_EQ(options.formFactors, FormFactorMethod::Analytic);
  CLI::App bad;
  SolveOptions unused;
  addSolveOptions(bad, unused);
  EXPECT_THROW(parse(bad, {"--solver", "multigrid"}), CLI::ValidationError);
}

TEST(OptionGroups, GatherOptionsAreRefusedOnlyWhenGiven) {
  CLI::App command;
  FinalGatherOptions rays{1, 0};
  addGatherOptions(command, rays, "hit");
  parse(command, {"--light-rays", "4"});
  EXPECT_EQ(rays.shadowRays(), 4);
  EXPECT_EQ(inputError([&] { refuseGatherOptions(command, "no gather"); }),
            "--light-rays is not used: no gather");
  CLI::App defaults;
  FinalGatherOptions same{1, 0};
  addGatherOptions(defaults, same, "hit");
  parse(defaults, {});
  EXPECT_EQ(inputError([&] { refuseGatherOptions(defaults, "no gather"); }), "");
  // compare binds --gather alone: asking about --light-rays is no error.
  CLI::App gatherOnly;
  addGatherRaysOption(gatherOnly, same, "hit");
  parse(gatherOnly, {"--gather", "2"});
  EXPECT_EQ(inputError([&] { refuseGatherOptions(gatherOnly, "no gather"); }),
            "--gather is not used: no gather");
  FinalGatherOptions negative{1, -1};
  EXPECT_EQ(inputError([&] { checkGatherOptions(negative); }), "--light-rays must be >= 0");
}

TEST(OptionGroups, TheGathersModeIsDecidedByItsTwoCounts) {
  EXPECT_EQ((FinalGatherOptions{4, 0}.shadowRays()), 4);
  EXPECT_EQ((FinalGatherOptions{4, 2}.shadowRays()), 2);
  EXPECT_TRUE((FinalGatherOptions{0, 2}.indirectFromSolution()));
  EXPECT_FALSE((FinalGatherOptions{1, 2}.indirectFromSolution()));
  EXPECT_FALSE((FinalGatherOptions{0, 0}.castsRays()));
  EXPECT_TRUE((FinalGatherOptions{0, 1}.castsRays()));
}

TEST(OptionGroups, ExposureMustBePositiveAndReplacesTheAutomaticOne) {
  CLI::App command;
  ExposureOption exposure;
  exposure.add(command, "exposure");
  parse(command, {});
  EXPECT_EQ(exposure.toneMap([] { return ToneMap{0.5}; }).exposure, 0.5);
  parse(command, {"--exposure", "2"});
  EXPECT_EQ(exposure.toneMap([] { return ToneMap{0.5}; }).exposure, 2.0);
  CLI::App zero;
  ExposureOption none;
  none.add(zero, "exposure");
  parse(zero, {"--exposure", "0"});
  EXPECT_EQ(inputError([&] { none.check(); }), "--exposure must be > 0");
}

TEST(OptionGroups, TheCameraLookUpSuggestsOnlyTheOptionsTheCommandBinds) {
  // A scene path with no sidecar camera beside it.
  const std::string scene =
      (std::filesystem::temp_directory_path() / "radiosity_no_camera_here.obj").string();
  CameraOptions all, sizeOnly;
  CLI::App render, compare;
  addCameraOptions(render, all, CameraOverrides::All);
  addCameraOptions(compare, sizeOnly, CameraOverrides::SizeOnly);
  EXPECT_NE(inputError([&] { resolveCamera(all, scene); }).find("or --position and --look-at"),
            std::string::npos);
  const std::string message = inputError([&] { resolveCamera(sizeOnly, scene); });
  EXPECT_NE(message.find("no camera"), std::string::npos) << message;
  EXPECT_EQ(message.find("--position"), std::string::npos) << message;
  // The command line alone places the camera; the overrides apply.
  parse(render, {"--position", "0", "0", "1", "--look-at", "0", "0", "0", "--width", "12"});
  const ResolvedCamera camera = resolveCamera(all, scene);
  EXPECT_EQ(camera.file, "");
  EXPECT_EQ(camera.camera.width, 12);
  EXPECT_EQ(camera.camera.position, Eigen::Vector3d(0, 0, 1));
  // A focus distance needs a lens: on a pinhole it is refused, with a lens radius it applies.
  all.focusDistance = 2;
  EXPECT_NE(inputError([&] { resolveCamera(all, scene); }).find("--focus-distance is not used"),
            std::string::npos);
  all.lensRadius = 0.01;
  EXPECT_EQ(resolveCamera(all, scene).camera.focusDistance, 2);
}

TEST(OptionGroups, ThreadsZeroMeansEveryHardwareThread) {
  EXPECT_EQ(threadCount(3), 3);
  EXPECT_EQ(threadCount(0), tbb::info::default_concurrency());
  const ThreadLimit limit(1);
  EXPECT_EQ(limit.threads(), 1);
  EXPECT_EQ(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism), 1u);
}

}  // namespace
}  // namespace rad
