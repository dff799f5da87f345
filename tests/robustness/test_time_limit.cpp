// --time-limit: progressive shooting stops at the deadline and the solution reached so far is
// written whole, flagged as not converged.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

TEST(TimeLimit, WritesAValidSolutionFlaggedAsNotConverged) {
  const auto out = testing::scratchPath("time_limit");
  const double limit = 1.5;
  // Tolerance 0, no iteration budget to speak of, and 20000 lazy rows of 1024 rays (several
  // seconds on this machine): only the deadline can stop it.
  const auto result =
      testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                            " --elements 20000 --tolerance 0 --max-iterations 2000000000"
                            " --time-limit " +
                            std::to_string(limit));
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_NE(result.stderrText.find("time limit"), std::string::npos) << result.stderrText;

  std::ifstream summaryFile(out / "summary.json");
  ASSERT_TRUE(summaryFile) << "no summary.json";
  const nlohmann::json summary = nlohmann::json::parse(summaryFile);
  EXPECT_EQ(summary["solver"]["converged"], false);
  EXPECT_EQ(summary["solver"]["stopped_by"], "time limit");
  // Stopped by the deadline, not before it: the run's own clock passed the limit.
  EXPECT_GE(summary["time_seconds"]["total"].get<double>(), limit);
  const int iterations = summary["solver"]["iterations"];
  EXPECT_GT(iterations, 0);
  const int elements = summary["scene"]["elements"];

  // elements.csv is complete: one row per element, finite non-negative radiosity, and the
  // light's own elements at least their emission π·Ke (Ke = 17, 12, 4 in the Cornell MTL).
  std::ifstream csv(out / "elements.csv");
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("element,patch,material", 0), 0u) << line;
  int rows = 0;
  double maxRed = 0;
  while (std::getline(csv, line)) {
    std::stringstream fields(line);
    std::vector<double> v;
    std::vector<std::string> f;
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    // 16 numbers, the 3 of E_d (Ed_r,Ed_g,Ed_b), then the buried cells (hexadecimal).
    ASSERT_EQ(f.size(), 20u) << line;
    for (size_t k = 0; k < 19; ++k) v.push_back(std::stod(f[k]));
    for (int k = 10; k < 19; ++k) ASSERT_TRUE(std::isfinite(v[k]) && v[k] >= 0) << line;
    maxRed = std::max(maxRed, v[10]);
    ++rows;
  }
  EXPECT_EQ(rows, elements);
  EXPECT_GE(maxRed, M_PI * 17 * (1 - 1e-9));
  EXPECT_TRUE(std::filesystem::exists(out / "vertex_colors.ply"));
  std::filesystem::remove_all(out);
}

TEST(TimeLimit, RejectsNegativeAndNonNumericValues) {
  // Each fails the option's own check as the command line is read (a usage error, 2).
  const std::pair<const char*, int> cases[] = {{"-1", 2}, {"abc", 2}, {"nan", 2}};
  for (const auto& [value, code] : cases) {
    const auto out = testing::scratchPath("time_limit_bad");
    const auto result = testing::runRadiosity("solve " + kCornell + " --out " + out.string() +
                                              " --time-limit " + value);
    EXPECT_EQ(result.exitCode, code) << value << "\n" << result.stderrText;
    EXPECT_NE(result.stderrText.find("--time-limit"), std::string::npos)
        << value << ": " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace
}  // namespace rad
