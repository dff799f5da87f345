// `radiosity solve --solver hierarchical` end to end: the files every solver writes, the
// hierarchy's report, agreement with Gauss–Seidel on the same mesh, and its bad options.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kData = RADIOSITY_DATA_DIR;

// Σ area · (B_r + B_g + B_b) over elements.csv: the power leaving the surfaces.
double leavingPower(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  double power = 0;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    // The 16 numeric columns (buried_cells, hexadecimal, follows).
    while (row.size() < 16 && std::getline(fields, field, ',')) row.push_back(std::stod(field));
    power += row[3] * (row[10] + row[11] + row[12]);
  }
  return power;
}

nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST(CliHierarchical, CornellBoxAgreesWithGaussSeidelAndReportsItsLinks) {
  const auto hierarchical = testing::scratchPath("hr_cornell");
  const auto gathering = testing::scratchPath("gs_cornell");
  const std::string scene = kData + "/cornell_box/cornell_box.obj --elements 600 --rays 1024";
  auto result = testing::runRadiosity("solve " + scene + " --solver hierarchical --out " +
                                      hierarchical.string());
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  result = testing::runRadiosity("solve " + scene + " --solver gauss-seidel --out " +
                                 gathering.string());
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;

  const nlohmann::json summary = readJson(hierarchical / "summary.json");
  EXPECT_EQ(summary["solver"]["name"], "hierarchical");
  EXPECT_TRUE(summary["solver"]["converged"]);
  const nlohmann::json& h = summary["hierarchy"];
  const int elements = summary["scene"]["elements"];
  EXPECT_EQ(h["nodes"].get<int>(), 2 * elements - 1);
  EXPECT_GT(h["links"].get<int64_t>(), 0);
  EXPECT_GT(h["clusters"].get<int>(), 0);
  EXPECT_LE(h["bytes_per_element"].get<double>(), 2048.0);
  EXPECT_GT(h["peak_memory_bytes"].get<double>(), 0);
  // The same light is reflected as with Gauss–Seidel over element rows: Σ A (B − E), the leaving
  // power less the emitted (half of it here, which both share exactly), within the two
  // estimates' Monte Carlo noise. Its seed-to-seed standard deviation at these settings is 0.67%
  // for the rows and 0.12% for the hierarchy (seeds 1-4 each, 2026-12-07: `radiosity solve
  // cornell_box.obj --elements 600 --rays 1024 --solver S --seed N`), so the difference of two
  // runs has σ = 0.68%: within 4σ, 2.7%.
  const double emitted = summary["solver"]["emitted_power"];
  const double gatheringEmitted = readJson(gathering / "summary.json")["solver"]["emitted_power"];
  EXPECT_NEAR(gatheringEmitted, emitted, 1e-9 * emitted);
  const double ratio = (leavingPower(hierarchical / "elements.csv") - emitted) /
                       (leavingPower(gathering / "elements.csv") - emitted);
  EXPECT_NEAR(ratio, 1.0, 0.027);
  for (const char* name : {"vertex_colors.ply", "solution.vtp", "solution.json"})
    EXPECT_TRUE(std::filesystem::is_regular_file(hierarchical / name)) << name;
  std::filesystem::remove_all(hierarchical);
  std::filesystem::remove_all(gathering);
}

TEST(CliHierarchical, BadOptionsAreRefusedAndNothingIsWritten) {
  const auto out = testing::scratchPath("hr_bad");
  const std::string cornell = kData + "/cornell_box/cornell_box.obj --out " + out.string();
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"--solver hierarchical --link-epsilon 0", "--link-epsilon must be"},
      {"--solver hierarchical --link-epsilon -1", "--link-epsilon must be"},
      {"--link-epsilon 1e-3", "--link-epsilon is not used"},
      {"--solver hierarchical --keep-factors", "--solver hierarchical"},
      {"--solver hierarchical --form-factors analytic", "--solver hierarchical"},
  };
  for (const auto& c : cases) {
    const auto result = testing::runRadiosity("solve " + cornell + " " + c.arguments);
    EXPECT_EQ(result.exitCode, 1) << c.arguments;
    EXPECT_NE(result.stderrText.find(c.message), std::string::npos)
        << c.arguments << ": " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.arguments;
  }
  const auto mirrors = testing::runRadiosity(
      "solve " + kData + "/cornell_box/cornell_box_mirror_glass.obj --solver hierarchical --out " +
      out.string());
  EXPECT_EQ(mirrors.exitCode, 1);
  EXPECT_NE(mirrors.stderrText.find("mirrors and glass"), std::string::npos) << mirrors.stderrText;
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace rad
