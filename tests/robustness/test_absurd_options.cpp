// Resource limits and absurd options on the command line (issue 9): refused before any work,
// with a message naming the option to change, a non-zero exit and no output.
#include <gtest/gtest.h>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

TEST(ResourceLimits, RowsThatCannotFitAreRefusedBeforeMeshing) {
  // 3·10^6 elements × 10^6 rays: tens of terabytes of rows. Refused at once, naming --elements.
  const auto out = testing::scratchPath("too_much_memory");
  const auto result = testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                                            " --elements 3000000 --rays 1000000");
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_NE(result.stderrText.find("--elements"), std::string::npos) << result.stderrText;
  EXPECT_NE(result.stderrText.find("memory"), std::string::npos) << result.stderrText;
  // Refused before the mesh is built: the log has no "mesh: " line (the mesh stage's report).
  EXPECT_EQ(result.stderrText.find("mesh: "), std::string::npos) << result.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(ResourceLimits, AbsurdOptionsAreRejectedWithTheirName) {
  // Exit 2 where the option's own type or range refuses the value as the command line is read
  // (usage), 1 where the solve options' check does (bad input).
  const struct {
    const char* arguments;
    const char* option;
    int exitCode;
  } cases[] = {{"--rays 0", "--rays", 1},
               {"--rays -5", "--rays", 1},
               {"--elements 0", "--elements", 2},
               {"--elements -3", "--elements", 2},
               {"--max-area -1", "--max-area", 1},
               {"--threads -2", "--threads", 2},
               {"--tolerance nan", "--tolerance", 1},
               {"--time-limit -1", "--time-limit", 2},
               {"--patch-area -1", "--patch-area", 1},
               {"--max-elements -1", "--max-elements", 1},
               {"--rays 99999999999", "--rays", 2}};
  for (const auto& c : cases) {
    const auto out = testing::scratchPath("absurd");
    const auto result =
        testing::runRadiosity("solve " + kCornell + " --out " + out.string() + " " + c.arguments);
    EXPECT_EQ(result.exitCode, c.exitCode) << c.arguments << "\n" << result.stderrText;
    EXPECT_NE(result.stderrText.find(c.option), std::string::npos)
        << c.arguments << ": " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.arguments;
  }
}

}  // namespace
}  // namespace rad
