// `radiosity solve` end to end on the bundled Cornell box: the files it promises, consistent
// with each other and with the physics they claim.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kData = RADIOSITY_DATA_DIR;

std::vector<std::vector<double>> readCsv(const std::filesystem::path& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    // The 16 numeric columns (buried_cells, hexadecimal, follows).
    while (row.size() < 16 && std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(CliSolve, CornellBoxWritesConsistentOutputs) {
  const auto out = testing::scratchPath("cornell");
  const auto result =
      testing::runRadiosity("solve " + kData + "/cornell_box/cornell_box.obj --out " +
                            out.string() + " --elements 300 --rays 256 --seed 4");
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  for (const char* name : {"elements.csv", "vertex_colors.ply", "summary.json"})
    EXPECT_TRUE(std::filesystem::is_regular_file(out / name)) << name;
  for (const auto& entry : std::filesystem::directory_iterator(out))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "leftover " << entry.path();

  std::ifstream summaryFile(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summaryFile);
  const int elements = summary["scene"]["elements"];
  EXPECT_EQ(summary["scene"]["emitters"], 1);
  EXPECT_EQ(summary["scene"]["patches"], 17);
  EXPECT_TRUE(summary["solver"]["converged"]);
  EXPECT_LE(summary["solver"]["final"].get<double>(), 1e-4);
  EXPECT_GT(summary["form_factors"]["rays_cast"].get<double>(), 0);
  EXPECT_FALSE(summary["skipped"].empty());

  std::string header;
  const auto rows = readCsv(out / "elements.csv", header);
  EXPECT_EQ(header.rfind("element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b", 0), 0u);
  ASSERT_EQ(static_cast<int>(rows.size()), elements);
  // Columns: 3 area, 10-12 B, 13-15 L. Areas add up to the box's surface; emitters hold at
  // least their own emission pi·Ke; nothing is negative; L = B / pi.
  double area = 0;
  int bright = 0;
  for (const auto& r : rows) {
    area += r[3];
    for (int c = 10; c < 13; ++c) {
      EXPECT_GE(r[c], 0.0);
      EXPECT_NEAR(r[c + 3], r[c] / M_PI, 1e-12 * r[c]);
    }
    if (r[10] >= M_PI * 17 && r[11] >= M_PI * 12 && r[12] >= M_PI * 4) ++bright;
  }
  EXPECT_NEAR(area, summary["scene"]["total_area"].get<double>(), 1e-9);
  EXPECT_EQ(bright, summary["scene"]["emitter_elements"].get<int>());
  std::filesystem::remove_all(out);
}

TEST(CliSolve, SameSeedGivesByteIdenticalCsvAndOtherSeedDiffers) {
  auto run = [](const std::string& name, int seed, int threads) {
    const auto out = testing::scratchPath(name);
    const auto r =
        testing::runRadiosity("solve " + kData + "/cornell_box/cornell_box.obj --out " +
                              out.string() + " --elements 150 --rays 64 --quiet --seed " +
                              std::to_string(seed) + " --threads " + std::to_string(threads));
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    std::ifstream in(out / "elements.csv");
    std::stringstream text;
    text << in.rdbuf();
    std::filesystem::remove_all(out);
    return text.str();
  };
  const std::string a = run("seed_a", 9, 2), b = run("seed_b", 9, 1), c = run("seed_c", 10, 2);
  EXPECT_EQ(a, b) << "a different thread count changed the result";
  EXPECT_NE(a, c);
}

TEST(CliSolve, AnalyticFormFactorsShootFromPatchesToElements) {
  const auto out = testing::scratchPath("cornell_analytic");
  const auto r = testing::runRadiosity("solve " + kData + "/cornell_box/cornell_box.obj --out " +
                                       out.string() +
                                       " --form-factors analytic --elements 300 --shadow-rays 4");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  std::ifstream summaryFile(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summaryFile);
  EXPECT_EQ(summary["form_factors"]["method"], "analytic");
  const int shooters = summary["form_factors"]["shooters"], elements = summary["scene"]["elements"];
  EXPECT_GT(shooters, 17);
  EXPECT_LT(shooters * 4, elements);  // patches are coarser than the elements they contain
  EXPECT_TRUE(summary["solver"]["converged"]);
  std::filesystem::remove_all(out);
}

TEST(CliSolve, JacobiBouncesInTheFurnaceBox) {
  // Furnace box: rho = 0.5, Ke = 1, so E = pi and after k bounces B = pi (1 − 0.5^(k+1)) / 0.5.
  const auto out = testing::scratchPath("furnace_bounces");
  const auto r =
      testing::runRadiosity("solve " + kData + "/tests/furnace_box.obj --out " + out.string() +
                            " --solver jacobi --bounces 3 --rays 64 --elements 100");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  std::string header;
  const double expected = M_PI * (1 - std::pow(0.5, 4)) / 0.5;
  for (const auto& row : readCsv(out / "elements.csv", header))
    for (int c = 10; c < 13; ++c) EXPECT_NEAR(row[c], expected, 1e-12 * expected);
  std::filesystem::remove_all(out);
}

// `solve --probes`: a grid of light probes over the box's bounds, in probes.json and probes.bin.
TEST(CliSolve, ProbesOnTheCornellBoxGrid) {
  const auto out = testing::scratchPath("cornell_probes");
  const auto r = testing::runRadiosity("solve " + kData + "/cornell_box/cornell_box.obj --out " +
                                       out.string() +
                                       " --elements 200 --rays 64 --probes 0.2 --probe-rays 256");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  // The box spans 0..0.556, 0..0.5488, 0..0.5592: floor(extent / 0.2) + 1 points on each axis.
  const int count = int(std::floor(0.556 / 0.2) + 1) * int(std::floor(0.5488 / 0.2) + 1) *
                    int(std::floor(0.5592 / 0.2) + 1);
  std::ifstream jsonFile(out / "probes.json");
  ASSERT_TRUE(jsonFile.good());
  const nlohmann::json probes = nlohmann::json::parse(jsonFile);
  ASSERT_EQ(static_cast<int>(probes["probes"].size()), count);
  for (const auto& p : probes["probes"]) {
    ASSERT_EQ(p["sh"].size(), 9u);
    for (int c = 0; c < 3; ++c) EXPECT_GT(p["sh"][0][c].get<double>(), 0);  // lit inside the box
  }
  EXPECT_EQ(std::filesystem::file_size(out / "probes.bin"),
            static_cast<uintmax_t>(12 + count * (12 + 108 + 4)));
  std::filesystem::remove_all(out);

  // A spacing of 0 is refused before the solve: nothing is written.
  const auto bad = testing::scratchPath("cornell_probes_zero");
  const auto r0 = testing::runRadiosity("solve " + kData + "/cornell_box/cornell_box.obj --out " +
                                        bad.string() + " --probes 0");
  EXPECT_EQ(r0.exitCode, 1);
  EXPECT_NE(r0.stderrText.find("--probes must be a positive number"), std::string::npos)
      << r0.stderrText;
  EXPECT_FALSE(std::filesystem::exists(bad));
}

}  // namespace
}  // namespace rad
