// Slivers (aspect ratio 1e6), coincident coplanar surfaces, a tiny emitter (1e-6 of the scene's
// area) and emitters 1e6 times brighter than each other, all in one closed room (see
// stress_scenes.h): no NaN or Inf anywhere, and energy balance. With one reflectance rho
// everywhere and every row summing to 1, what shooting moves is conserved exactly:
// sum A_i B_i = (P − rho U) / (1 − rho), P the emitted and U the unshot power (see below).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "radiosity/core/log.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "tests/stress/stress_scenes.h"

namespace rad {
namespace {

constexpr double kRho = 0.6;

void expectFinite(const SolveResult& result) {
  for (int e = 0; e < static_cast<int>(result.solution.radiosity.size()); ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(result.solution.radiosity[e][c]))
          << "element " << e << " channel " << c;
      ASSERT_GE(result.solution.radiosity[e][c], result.solution.problem.emission[e][c])
          << "element " << e;
    }
  ASSERT_TRUE(std::isfinite(result.report.finalProgress));
}

SolveResult solveHostile(SolveOptions options) {
  setLogLevel(LogLevel::Quiet);
  options.scenePath = testing::writeHostileRoom(kRho);
  options.targetElements = 600;
  options.raysPerElement = 512;
  options.threads = 2;
  return runSolve(options);
}

TEST(DegenerateGeometry, SceneKeepsEveryStressedFace) {
  const SolveResult result = solveHostile({});
  EXPECT_EQ(result.solution.scene.skippedDegenerateFaces, 0);
  EXPECT_EQ(result.solution.scene.polygons.size(), 6u + 3u + 2u + 6u);
}

// Shooting moves power S; receivers get all of it (rows sum to 1) and reflect rho of it, so
// sum A B = P + rho S and U = P + rho S − S, hence sum A B = (P − rho U) / (1 − rho).
TEST(DegenerateGeometry, ProgressiveShootingIsFiniteAndBalancesEnergy) {
  SolveOptions options;
  options.tolerance = 1e-6;
  const SolveResult result = solveHostile(options);
  expectFinite(result);
  ASSERT_TRUE(result.report.converged);
  const RadiosityProblem& p = result.solution.problem;
  for (int c = 0; c < 3; ++c) {
    double total = 0, emitted = 0;
    for (int e = 0; e < p.size(); ++e) {
      total += p.area[e] * result.solution.radiosity[e][c];
      emitted += p.area[e] * p.emission[e][c];
    }
    const double balance = total * (1 - kRho) / emitted;
    std::cout << "channel " << c << ": sum A B (1 − rho) / P = " << balance << ", unshot fraction "
              << result.report.finalProgress << "\n";
    // The deficit is rho × the unshot fraction (at most the tolerance), nothing else.
    EXPECT_LE(balance, 1 + 1e-9);
    EXPECT_GE(balance, 1 - kRho * options.tolerance - 1e-9);
  }
}

TEST(DegenerateGeometry, GaussSeidelIsFiniteAndConverges) {
  SolveOptions options;
  options.solver = SolverKind::GaussSeidel;
  options.tolerance = 1e-8;
  const SolveResult result = solveHostile(options);
  expectFinite(result);
  EXPECT_TRUE(result.report.converged) << "residual " << result.report.finalProgress;
}

TEST(DegenerateGeometry, AnalyticFormFactorsAreFinite) {
  SolveOptions options;
  options.formFactors = FormFactorMethod::Analytic;
  const SolveResult result = solveHostile(options);
  expectFinite(result);
  EXPECT_TRUE(result.report.converged) << "unshot fraction " << result.report.finalProgress;
}

}  // namespace
}  // namespace rad
