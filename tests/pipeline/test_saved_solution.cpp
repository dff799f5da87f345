// Saved solutions (radiosity/pipeline/saved_solution.h): what writeSavedSolution keeps,
// loadSavedSolution reads back for the same scene and solve options, bit-exact: B per element,
// and E_d per element (Solution::directIrradiance); a solution written without E_d reads back
// without it, and solveOrReuse does not take it for the split.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/core/atomic_file.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/pipeline/solution_source.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

SolveOptions smallSolve() {
  SolveOptions o;
  o.scenePath = kCornell;
  o.targetElements = 200;
  o.raysPerElement = 64;
  o.threads = 2;
  return o;
}

// One small solve of the Cornell box, shared by the tests (each sets what it writes).
SolveResult& solved() {
  static SolveResult result = solveScene(loadScene(kCornell), smallSolve());
  return result;
}

// A fresh directory for one test's saved solution.
std::string freshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("radiosity_saved_solution_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

void save(const SolveResult& result, const std::string& dir) {
  AtomicFile csv(dir + "/" + kSolutionCsv), json(dir + "/" + kSolutionJson);
  writeSavedSolution(csv, json, result, smallSolve());
  commitAll({&csv, &json});
}

std::string firstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

SolveResult load(const std::string& dir) {
  std::string whyNot;
  std::optional<SolveResult> loaded =
      loadSavedSolution(dir, loadScene(kCornell), smallSolve(), whyNot);
  if (!loaded) throw std::runtime_error("not reused: " + whyNot);
  return std::move(*loaded);
}

void expectSameRadiosity(const std::vector<Rgb>& got, const std::vector<Rgb>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t e = 0; e < want.size(); ++e)
    for (int c = 0; c < 3; ++c) ASSERT_EQ(got[e][c], want[e][c]) << "element " << e << " " << c;
}

// E_d set: the CSV has the Ed columns and a reuse reads them back bit-exact, whether or not the
// buried cells follow them (a solution without an exposure writes none).
TEST(SavedSolution, DirectIrradianceReadsBackBitExact) {
  SolveResult& result = solved();
  const int count = result.solution.mesh->elementCount();
  ASSERT_GT(count, 100);
  std::vector<Rgb> direct(count);
  for (int e = 0; e < count; ++e)  // values with no short decimal form, and zeros
    direct[e] = e % 7 == 0 ? Rgb(0, 0, 0) : Rgb(1.0 / (e + 3), 0.1 * e + 1.0 / 7, 3.0 / e);
  result.solution.directIrradiance = direct;
  const std::shared_ptr<const ElementExposure> exposure = result.solution.exposure;
  ASSERT_NE(exposure, nullptr);
  for (const bool withExposure : {true, false}) {
    SCOPED_TRACE(withExposure ? "with buried cells" : "without buried cells");
    result.solution.exposure = withExposure ? exposure : nullptr;
    const std::string dir = freshDir(withExposure ? "ed_buried" : "ed");
    save(result, dir);
    EXPECT_EQ(firstLine(dir + "/" + kSolutionCsv), std::string(kElementsCsvHeader) +
                                                       ",Ed_r,Ed_g,Ed_b" +
                                                       (withExposure ? ",buried_cells" : ""));
    const SolveResult loaded = load(dir);
    EXPECT_TRUE(loaded.report.reusedSavedSolution);
    expectSameRadiosity(loaded.solution.radiosity, result.solution.radiosity);
    expectSameRadiosity(loaded.solution.directIrradiance, direct);
    std::filesystem::remove_all(dir);
  }
  result.solution.exposure = exposure;
  // Not one value per element: the writer refuses.
  result.solution.directIrradiance.resize(count - 1);
  std::ostringstream out;
  EXPECT_THROW(writeSolutionElementsCsv(out, result.solution), CheckFailure);
  result.solution.directIrradiance.clear();
}

// E_d not known: no Ed columns; the solution reads back without it, and is not reused where the
// split needs it.
TEST(SavedSolution, WithoutDirectIrradianceReadsBackEmptyAndTheSplitDoesNotReuseIt) {
  SolveResult& result = solved();
  result.solution.directIrradiance.clear();
  const std::string dir = freshDir("no_ed");
  save(result, dir);
  EXPECT_EQ(firstLine(dir + "/" + kSolutionCsv), std::string(kElementsCsvHeader) + ",buried_cells");
  const SolveResult loaded = load(dir);
  expectSameRadiosity(loaded.solution.radiosity, result.solution.radiosity);
  EXPECT_TRUE(loaded.solution.directIrradiance.empty());
  SolutionSource split{dir, "", /*needsDirectIrradiance=*/true};
  try {
    solveOrReuse(loadScene(kCornell), smallSolve(), split);
    ADD_FAILURE() << "reused a solution without E_d for the split";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Ed_r,Ed_g,Ed_b"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rad
