// How the command line turns what a command throws into its exit code (runCommand, as main.cpp
// runs every subcommand): a failed internal check is a bug (3), bad input is the user's (1).
#include <gtest/gtest.h>

#include <cstdlib>

#include "radiosity/app/exit_codes.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {
namespace {

TEST(ExitCodes, SuccessIsZero) {
  EXPECT_EQ(runCommand([] {}), kExitSuccess);
}

// The death tests run their child as a fresh process of this binary ("threadsafe"), not a fork:
// a library loaded with the program may start a thread (OpenImageIO's log4cplus does), and a
// forked child, which has none of the parent's threads, then hangs in that library's exit
// handler waiting for it (seen under the clang sanitizer build, which links every library).
class ExitCodesDeathTest : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(ExitCodesDeathTest, FailedCheckExits3AsABug) {
  EXPECT_EXIT(std::exit(runCommand([] {
                const int vertices = 4, values = 3;
                RAD_CHECK_EQ(values, vertices);
              })),
              ::testing::ExitedWithCode(3),
              "internal error \\(a bug, please report it\\): bug in radiosity: .*test_exit_codes"
              "\\.cpp:[0-9]+: check failed: values == vertices \\(3 vs 4\\)");
}

TEST_F(ExitCodesDeathTest, InputErrorStillExits1) {
  EXPECT_EXIT(std::exit(runCommand([] { throw InputError("scene.obj", 7, "unknown material"); })),
              ::testing::ExitedWithCode(1), "error: scene.obj:7: unknown material");
}

TEST_F(ExitCodesDeathTest, OtherFailuresExit1) {
  EXPECT_EXIT(std::exit(runCommand([] { throw RuntimeFailure("disk full"); })),
              ::testing::ExitedWithCode(1), "error: disk full");
}

}  // namespace
}  // namespace rad
