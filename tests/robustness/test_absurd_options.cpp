// Resource limits and absurd options on the command line (issue 9): refused before any work,
// with a message naming the option to change, a non-zero exit and no output.
#include <gtest/gtest.h>

#include <chrono>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

TEST(ResourceLimits, RowsThatCannotFitAreRefusedBeforeMeshing) {
  // 3·10^6 elements × 10^6 rays: tens of terabytes of rows. Refused at once, naming --elements.
  const auto out = testing::scratchPath("too_much_memory");
  const auto start = std::chrono::steady_clock::now();
  const auto result = testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                                            " --elements 3000000 --rays 1000000");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find("--elements"), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find("memory"), std::string::npos) << result.stderrText;
  EXPECT_LT(seconds, 5) << "the check must come before the mesh is built";
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ResourceLimits, AbsurdOptionsAreRejectedWithTheirName) {
  const char* cases[][2] = {{"--rays 0", "--rays"},
                            {"--rays -5", "--rays"},
                            {"--elements 0", "--elements"},
                            {"--elements -3", "--elements"},
                            {"--max-area -1", "--max-area"},
                            {"--threads -2", "--threads"},
                            {"--tolerance nan", "--tolerance"},
                            {"--time-limit -1", "--time-limit"},
                            {"--patch-area -1", "--patch-area"},
                            {"--max-elements -1", "--max-elements"},
                            {"--rays 99999999999", "--rays"}};
  for (const auto& c : cases) {
    const auto out = testing::scratchPath("absurd");
    const auto result =
        testing::runRadiosity("solve " + kCornell + " --out " + out.string() + " " + c[0]);
    EXPECT_NE(result.exitCode, 0) << c[0];
    EXPECT_TRUE(result.exitCode == 1 || result.exitCode == 2)
        << c[0] << ": exit " << result.exitCode;
    EXPECT_NE(result.stderrText.find(c[1]), std::string::npos) << c[0] << ": " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out)) << c[0];
  }
}

}  // namespace
}  // namespace rad
