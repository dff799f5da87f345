// `radiosity solve --keep-factors` then `radiosity relight DIR --override FILE`, end to end: the
// outputs rewritten with no ray cast, the same answer as solving the changed scene, and bad input
// (a wrong override, no kept factors, a scene that changed) refused with the old outputs intact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "radiosity/output/elements_csv.h"
#include "radiosity/output/image_io.h"
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

// A copy of the Cornell box (OBJ + MTL) in `dir`, its red wall's Kd replaced when `red` is given.
fs::path copyCornell(const fs::path& dir, const std::string& red = "") {
  fs::create_directories(dir);
  fs::copy_file(kData + "/cornell_box/cornell_box.obj", dir / "cornell_box.obj");
  std::string mtl = readText(kData + "/cornell_box/cornell_box.mtl");
  if (!red.empty()) {
    const size_t at = mtl.find("Kd", mtl.find("newmtl red"));
    mtl.replace(at, mtl.find('\n', at) - at, "Kd " + red);
  }
  std::ofstream(dir / "cornell_box.mtl") << mtl;
  return dir / "cornell_box.obj";
}

// L = B/π per element and channel, as elements.csv holds it.
std::vector<double> radiosityColumn(const fs::path& csv) {
  std::vector<double> values;
  for (const ElementsCsvRow& row : readElementsCsv(csv.string()).rows)
    values.insert(values.end(), {row.radiance.r, row.radiance.g, row.radiance.b});
  return values;
}

const std::string kSolveOptions = " --elements 200 --rays 64 --tolerance 1e-9 --quiet";

TEST(CliRelight, MatchesASolveOfTheChangedSceneAndCastsNoRay) {
  const fs::path root = scratchPath("relight");
  const fs::path scene = copyCornell(root / "scene");
  const fs::path kept = root / "kept";
  ASSERT_EQ(runRadiosity("solve " + scene.string() + " --out " + kept.string() + " --keep-factors" +
                         kSolveOptions)
                .exitCode,
            0);
  ASSERT_TRUE(fs::exists(kept / "factors.bin"));
  std::ofstream(root / "over.json") << R"({"materials": {"red": {"diffuse": [0.1, 0.2, 0.6]}}})";
  // The same change made in the MTL and solved afresh, by the kept solve's solver (progressive,
  // relight's default) and by Gauss–Seidel (relight --solver gauss-seidel): each pair equal to
  // the tolerance, since the rows are the same rays.
  const fs::path changed = copyCornell(root / "changed", "0.1 0.2 0.6");
  for (const std::string solver : {"", " --solver gauss-seidel"}) {
    const fs::path relit = root / ("relit" + std::to_string(solver.size()));
    const auto r =
        runRadiosity("relight " + kept.string() + " --override " + (root / "over.json").string() +
                     " --out " + relit.string() + solver + " --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    const auto summary = nlohmann::json::parse(readText(relit / "summary.json"));
    EXPECT_EQ(summary["relight"]["rays_cast"].get<long>(), 0);
    const fs::path fresh = root / ("fresh" + std::to_string(solver.size()));
    ASSERT_EQ(runRadiosity("solve " + changed.string() + " --out " + fresh.string() +
                           " --keep-factors" + kSolveOptions + solver)
                  .exitCode,
              0);
    const std::vector<double> a = radiosityColumn(fresh / "elements.csv");
    const std::vector<double> b = radiosityColumn(relit / "elements.csv");
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    double peak = 0;
    for (double v : a) peak = std::max(peak, v);
    for (size_t i = 0; i < a.size(); ++i) ASSERT_NEAR(b[i], a[i], 1e-5 * peak) << solver << i;
  }
  fs::remove_all(root);
}

// The Cornell box's two lamps (data/cornell_box/two_lamps.lights.json), their intensities scaled
// per channel: the spot (group "lamp") by `spot`, the point light by `point`.
fs::path writeLamps(const fs::path& path, const std::string& spot, const std::string& point) {
  std::ofstream(path) << R"({"lights": [
    {"type": "spot", "position": [0.15, 0.5, 0.45], "direction": [0.1, -1, -0.1],
     "intensity": )" << spot
                      << R"(, "cone_degrees": 35, "inner_cone_degrees": 25, "group": "lamp"},
    {"type": "point", "position": [0.45, 0.45, 0.1], "intensity": )"
                      << point << "}]}";
  return path;
}

std::vector<double> lightmap(const fs::path& dir) {
  std::vector<double> channels;
  for (const Rgb& p : readExr((dir / "lightmap.exr").string()).pixels)
    channels.insert(channels.end(), {p.r, p.g, p.b});
  return channels;
}

// `bake --solution` on a relit directory bakes the relit solution: the scene's files with the
// override applied (solution.json keeps it), as a bake of a scene with the change made would.
TEST(CliRelight, BakeOfTheRelitSolutionIsTheBakeOfTheChangedScene) {
  const fs::path root = scratchPath("relight_bake");
  const fs::path scene = copyCornell(root / "scene");
  const fs::path lamps = writeLamps(root / "lamps.json", "[0.05, 0.15, 0.3]", "[0.3, 0.18, 0.06]");
  const std::string options = kSolveOptions + " --solver gauss-seidel";
  const fs::path kept = root / "kept";
  ASSERT_EQ(runRadiosity("solve " + scene.string() + " --lights " + lamps.string() + " --out " +
                         kept.string() + " --keep-factors" + options)
                .exitCode,
            0);
  std::ofstream(root / "over.json") << R"({"materials": {"red": {"diffuse": [0.1, 0.2, 0.6]}},
    "lights": {"lamp": {"scale": 3}, "1": {"scale": [1, 0.5, 0.25]}}})";
  const fs::path relit = root / "relit";
  auto r =
      runRadiosity("relight " + kept.string() + " --override " + (root / "over.json").string() +
                   " --out " + relit.string() + " --solver gauss-seidel --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  auto bake = [&](const fs::path& obj, const fs::path& lights, const fs::path& solution,
                  const fs::path& out) {
    const auto b =
        runRadiosity("bake " + obj.string() + " --lights " + lights.string() + " --solution " +
                     solution.string() + " --out " + out.string() + options);
    EXPECT_EQ(b.exitCode, 0) << b.stderrText;
    EXPECT_TRUE(nlohmann::json::parse(readText(out / "bake.json"))["reused_saved_solution"]);
    return lightmap(out);
  };
  const std::vector<double> relitMap = bake(scene, lamps, relit, root / "baked_relit");
  const std::vector<double> keptMap = bake(scene, lamps, kept, root / "baked_kept");
  // The change made in the files and solved afresh (the same rows: the same rays).
  const fs::path changed = copyCornell(root / "changed", "0.1 0.2 0.6");
  const fs::path changedLamps =
      writeLamps(root / "changed_lamps.json", "[0.15, 0.45, 0.9]", "[0.3, 0.09, 0.015]");
  const fs::path fresh = root / "fresh";
  ASSERT_EQ(runRadiosity("solve " + changed.string() + " --lights " + changedLamps.string() +
                         " --out " + fresh.string() + " --keep-factors" + options)
                .exitCode,
            0);
  const std::vector<double> freshMap = bake(changed, changedLamps, fresh, root / "baked_fresh");
  ASSERT_EQ(relitMap.size(), freshMap.size());
  ASSERT_EQ(keptMap.size(), freshMap.size());
  ASSERT_FALSE(freshMap.empty());
  const double peak = *std::max_element(freshMap.begin(), freshMap.end());
  double changedMost = 0;
  for (size_t i = 0; i < freshMap.size(); ++i) {
    // The factors are kept as floats (6e-8 relative): the solutions agree to 1e-5 of the peak.
    ASSERT_NEAR(relitMap[i], freshMap[i], 1e-5 * peak) << "texel channel " << i;
    changedMost = std::max(changedMost, std::abs(relitMap[i] - keptMap[i]));
  }
  EXPECT_GT(changedMost, 0.05 * peak);

  // A relit solution.json whose overrides were edited into nonsense: the file and the pointer of
  // the bad value, and no output directory.
  const std::string good = readText(relit / "solution.json");
  auto refused = [&](const std::string& from, const std::string& to, const std::string& pointer) {
    std::string json = good;
    ASSERT_NE(json.find(from), std::string::npos) << from;
    json.replace(json.find(from), from.size(), to);
    std::ofstream(relit / "solution.json") << json;
    const auto b =
        runRadiosity("bake " + scene.string() + " --lights " + lamps.string() + " --solution " +
                     relit.string() + " --out " + (root / "bad").string() + options);
    EXPECT_EQ(b.exitCode, 1) << pointer;
    EXPECT_NE(b.stderrText.find("solution.json"), std::string::npos) << b.stderrText;
    EXPECT_NE(b.stderrText.find(pointer), std::string::npos) << b.stderrText;
    EXPECT_FALSE(fs::exists(root / "bad"));
  };
  refused("\"light_scale\"", "\"light_scale\": 7, \"x\"", "/relit/light_scale");
  refused("\"index\": 1", "\"index\": \"one\"", "/relit/materials/0");
  refused("0.1,", "-0.1,", "/relit/materials/0/diffuse");
  fs::remove_all(root);
}

TEST(CliRelight, BadInputFailsAndLeavesTheOutputsAsTheyWere) {
  const fs::path root = scratchPath("relight_bad");
  const fs::path scene = copyCornell(root / "scene");
  const fs::path kept = root / "kept";
  ASSERT_EQ(runRadiosity("solve " + scene.string() + " --out " + kept.string() + " --keep-factors" +
                         kSolveOptions)
                .exitCode,
            0);
  const std::string before = readText(kept / "elements.csv");
  // An unknown material: the override file's line and pointer.
  std::ofstream(root / "over.json")
      << "{\"materials\": {\n  \"purple\": {\"diffuse\": [1, 0, 1]}}}";
  auto r =
      runRadiosity("relight " + kept.string() + " --override " + (root / "over.json").string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("over.json:2"), std::string::npos) << r.stderrText;
  EXPECT_NE(r.stderrText.find("/materials/purple"), std::string::npos) << r.stderrText;
  // A light index the kept solve does not have (the box has no lights).
  std::ofstream(root / "over.json") << R"({"lights": {"0": {"scale": 2}}})";
  r = runRadiosity("relight " + kept.string() + " --override " + (root / "over.json").string());
  EXPECT_EQ(r.exitCode, 1);
  // The scene moved since the solve.
  std::string obj = readText(scene);
  obj.replace(obj.find("\nv ") + 3, 1, "0.01 ");
  std::ofstream(scene) << obj;
  r = runRadiosity("relight " + kept.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("changed since"), std::string::npos) << r.stderrText;
  EXPECT_EQ(readText(kept / "elements.csv"), before);
  // A directory without kept factors.
  r = runRadiosity("relight " + root.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.stderrText.find("--keep-factors"), std::string::npos) << r.stderrText;
  // Options --keep-factors cannot keep.
  r = runRadiosity("solve " + scene.string() + " --out " + (root / "x").string() +
                   " --keep-factors --form-factors analytic");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(fs::exists(root / "x"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace rad
