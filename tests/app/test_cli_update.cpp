// `radiosity solve --keep-factors`, an edit of the scene's geometry, then `radiosity update DIR`,
// end to end: the outputs rewritten with most rows reused, the same answer as solving the edited
// scene afresh, a second update from the first's factors, and bad input (among it a material
// given a cut-out) refused with the old outputs intact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "radiosity/output/elements_csv.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kData = RADIOSITY_DATA_DIR;

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The Cornell box in `dir` with the tall block's 8 vertices shifted by (dx, 0, dz).
fs::path writeCornell(const fs::path& dir, double dx, double dz) {
  fs::create_directories(dir);
  fs::copy_file(kData + "/cornell_box/cornell_box.mtl", dir / "cornell_box.mtl",
                fs::copy_options::overwrite_existing);
  std::istringstream in(readText(kData + "/cornell_box/cornell_box.obj"));
  std::ofstream out(dir / "cornell_box.obj");
  std::string line;
  int moved = -1;
  while (std::getline(in, line)) {
    if (line == "o tall_block") moved = 0;
    if (moved >= 0 && moved < 8 && line.rfind("v ", 0) == 0) {
      std::istringstream v(line.substr(2));
      double x, y, z;
      v >> x >> y >> z;
      std::ostringstream s;
      s.precision(17);
      s << "v " << x + dx << " " << y << " " << z + dz;
      line = s.str();
      ++moved;
    }
    out << line << "\n";
  }
  return dir / "cornell_box.obj";
}

// B per element and channel, as elements.csv holds it.
std::vector<double> radiosityColumn(const fs::path& csv) {
  std::vector<double> values;
  for (const ElementsCsvRow& row : readElementsCsv(csv.string()).rows)
    values.insert(values.end(), {row.radiosity.r, row.radiosity.g, row.radiosity.b});
  return values;
}

const std::string kSolveOptions =
    " --keep-factors --solver gauss-seidel --element-size 0.07 --rays 64 --tolerance 1e-9 --quiet";

void expectSameSolution(const fs::path& a, const fs::path& b) {
  const std::vector<double> x = radiosityColumn(a / "elements.csv");
  const std::vector<double> y = radiosityColumn(b / "elements.csv");
  ASSERT_EQ(x.size(), y.size());
  ASSERT_FALSE(x.empty());
  double peak = 0;
  for (double v : y) peak = std::max(peak, v);
  // The same rows (kept ones as floats) and both converged to 1e-9: equal to float rounding.
  for (size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(x[i], y[i], 2e-6 * peak) << "value " << i;
}

TEST(CliUpdate, MovedBlockMatchesAFreshSolveTwiceOver) {
  const fs::path root = scratchPath("update");
  const fs::path kept = root / "kept";
  const fs::path scene = writeCornell(root / "scene", 0, 0);
  ASSERT_EQ(
      runRadiosity("solve " + scene.string() + " --out " + kept.string() + kSolveOptions).exitCode,
      0);
  const std::string before = readText(kept / "elements.csv");
  for (const auto& [dx, dz] : {std::pair{0.03, -0.02}, std::pair{0.05, -0.06}}) {
    writeCornell(root / "scene", dx, dz);  // the user edits the scene in place
    const auto r = runRadiosity("update " + kept.string() + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const fs::path fresh = root / ("fresh" + std::to_string(dx));
    const fs::path edited = writeCornell(fresh / "scene", dx, dz);
    ASSERT_EQ(runRadiosity("solve " + edited.string() + " --out " + (fresh / "out").string() +
                           kSolveOptions)
                  .exitCode,
              0);
    expectSameSolution(kept, fresh / "out");
    const auto summary = nlohmann::json::parse(readText(kept / "summary.json"));
    const auto& u = summary.at("update");
    EXPECT_GT(u.at("elements_moved_or_added").get<int>(), 0);
    EXPECT_GT(u.at("rows_updated_ray_by_ray").get<int>(), 0);
    EXPECT_GT(u.at("rows_cast_again").get<int>(), 0);
    EXPECT_EQ(u.at("rows_reused").get<int>() + u.at("rows_updated_ray_by_ray").get<int>() +
                  u.at("rows_cast_again").get<int>(),
              summary.at("scene").at("elements").get<int>());
  }
  EXPECT_NE(readText(kept / "elements.csv"), before);
  // The re-bake reuses the updated solution: the same options as the solve, no solve.
  const auto bake = runRadiosity(
      "bake " + scene.string() + " --out " + (root / "baked").string() + " --solution " +
      kept.string() + " --no-lightmap --solver gauss-seidel --element-size 0.07 --rays 64 " +
      "--tolerance 1e-9 --quiet");
  ASSERT_EQ(bake.exitCode, 0) << bake.stderrText;
  EXPECT_TRUE(nlohmann::json::parse(readText(root / "baked" / "bake.json"))
                  .at("reused_saved_solution")
                  .get<bool>());
}

TEST(CliUpdate, BadInputLeavesTheOutputsAsTheyWere) {
  const fs::path root = scratchPath("update_bad");
  const fs::path kept = root / "kept";
  const fs::path scene = writeCornell(root / "scene", 0, 0);
  ASSERT_EQ(
      runRadiosity("solve " + scene.string() + " --out " + kept.string() + kSolveOptions).exitCode,
      0);
  const std::string csv = readText(kept / "elements.csv");
  // No kept factors here.
  auto r = runRadiosity("update " + (root / "scene").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("--keep-factors"), std::string::npos) << r.stderrText;
  // Southwell (shooting along the gathering matrix's columns) cannot start from the previous
  // solution.
  r = runRadiosity("update " + kept.string() + " --solver southwell");
  EXPECT_EQ(r.exitCode, 2) << r.stderrText;  // not one of the option's choices: usage
  EXPECT_NE(r.stderrText.find("--solver"), std::string::npos) << r.stderrText;
  // An elements.csv of another solve (one element): named, and left as it was.
  const std::string oneRow = csv.substr(0, csv.find('\n', csv.find('\n') + 1) + 1);
  std::ofstream(kept / "elements.csv", std::ios::binary) << oneRow;
  r = runRadiosity("update " + kept.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("elements.csv"), std::string::npos) << r.stderrText;
  EXPECT_NE(r.stderrText.find("not the same solve"), std::string::npos) << r.stderrText;
  EXPECT_EQ(readText(kept / "elements.csv"), oneRow);
  std::ofstream(kept / "elements.csv", std::ios::binary) << csv;
  // A cut-short factors.bin.
  const std::string factors = readText(kept / "factors.bin");
  std::ofstream(kept / "factors.bin", std::ios::binary) << factors.substr(0, factors.size() / 2);
  r = runRadiosity("update " + kept.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("factors.bin"), std::string::npos) << r.stderrText;
  EXPECT_EQ(readText(kept / "elements.csv"), csv);
  std::ofstream(kept / "factors.bin", std::ios::binary) << factors;
  // The red wall given a cut-out mask (a 1×1 grey TGA) with no vertex moved: rays now pass where
  // they stopped, which no edit region holds. Refused, naming the material.
  const std::string tga = {0,
                           0,
                           2,
                           0,
                           0,
                           0,
                           0,
                           0,
                           0,
                           0,
                           0,
                           0,
                           1,
                           0,
                           1,
                           0,
                           24,
                           0,
                           static_cast<char>(100),
                           static_cast<char>(100),
                           static_cast<char>(100)};
  std::ofstream(root / "scene" / "mask.tga", std::ios::binary) << tga;
  std::string mtl = readText(root / "scene" / "cornell_box.mtl");
  mtl.insert(mtl.find("\n", mtl.find("newmtl red")) + 1, "map_d mask.tga\n");
  std::ofstream(root / "scene" / "cornell_box.mtl", std::ios::binary) << mtl;
  r = runRadiosity("update " + kept.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("material 'red' stops rays differently"), std::string::npos)
      << r.stderrText;
  EXPECT_NE(r.stderrText.find("solve --keep-factors again"), std::string::npos) << r.stderrText;
  EXPECT_EQ(readText(kept / "elements.csv"), csv);
  EXPECT_EQ(readText(kept / "factors.bin"), factors);
}

}  // namespace
}  // namespace rad
