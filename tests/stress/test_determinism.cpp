// Determinism: the same seed and thread count give bit-identical radiosity and output files,
// for every form-factor method and solver, with specular continuation and with refinement
// (where thread scheduling could change the order of floating-point sums).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "radiosity/app/solve_outputs.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/solve_pipeline.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

struct Case {
  const char* name;
  const char* scene;
  SolverKind solver;
  FormFactorMethod method;
  double refine;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Determinism : public ::testing::TestWithParam<Case> {};

TEST_P(Determinism, SameSeedAndThreadsGiveIdenticalBits) {
  const Case c = GetParam();
  setLogLevel(LogLevel::Quiet);
  SolveOptions options;
  options.scenePath = std::string(RADIOSITY_DATA_DIR) + c.scene;
  options.solver = c.solver;
  options.formFactors = c.method;
  options.refineThreshold = c.refine;
  options.refinePasses = 1;
  options.targetElements = 500;
  options.raysPerElement = 256;
  options.threads = 2;
  options.seed = 42;
  const fs::path base =
      fs::temp_directory_path() / ("radiosity_determinism_" + std::to_string(getpid()) + c.name);
  std::string files[2][2];
  std::vector<Rgb> radiosity[2];
  for (int run = 0; run < 2; ++run) {
    options.outputDir = (base / std::to_string(run)).string();
    SolveResult result = runSolve(options);
    radiosity[run] = result.solution.radiosity;
    writeSolveOutputs(options, result);
    files[run][0] = readFile(fs::path(options.outputDir) / "elements.csv");
    files[run][1] = readFile(fs::path(options.outputDir) / "vertex_colors.ply");
  }
  fs::remove_all(base);
  ASSERT_EQ(radiosity[0].size(), radiosity[1].size());
  ASSERT_FALSE(radiosity[0].empty());
  EXPECT_EQ(
      std::memcmp(radiosity[0].data(), radiosity[1].data(), radiosity[0].size() * sizeof(Rgb)), 0);
  ASSERT_FALSE(files[0][0].empty());
  EXPECT_TRUE(files[0][0] == files[1][0]) << "elements.csv differs";
  EXPECT_TRUE(files[0][1] == files[1][1]) << "vertex_colors.ply differs";
}

INSTANTIATE_TEST_SUITE_P(
    AllMethods, Determinism,
    ::testing::Values(Case{"progressive", "/cornell_box/cornell_box.obj", SolverKind::Progressive,
                           FormFactorMethod::Hemisphere, 0},
                      Case{"gauss_seidel", "/cornell_box/cornell_box.obj", SolverKind::GaussSeidel,
                           FormFactorMethod::Hemisphere, 0},
                      Case{"mirror_glass", "/cornell_box/cornell_box_mirror_glass.obj",
                           SolverKind::Progressive, FormFactorMethod::Hemisphere, 0},
                      Case{"analytic_refined", "/cornell_box/cornell_box.obj",
                           SolverKind::Progressive, FormFactorMethod::Analytic, 0.3}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace rad
