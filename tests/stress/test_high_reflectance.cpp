// Reflectance close to 1 in a closed box (furnace, ../shared/REFERENCES.md): B = E/(1−rho)
// exactly whatever the form factors, since every row sums to 1. Near rho = 1 the system is
// nearly singular (condition ~ 1/(1−rho)); the solvers must still get there.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

struct NearlyWhiteFurnace {
  PatchMesh mesh = testing::closedCube(0.05);
  RayCaster rays{mesh};
  HemisphereFormFactors method{mesh, rays, {256, 11}};
  FormFactorCache cache{method};
  RadiosityProblem problem;
  explicit NearlyWhiteFurnace(double rho) {
    for (int e = 0; e < mesh.elementCount(); ++e) {
      problem.emission.push_back(Rgb(1.0, 0.5, 2.0));
      problem.reflectance.push_back(Rgb::all(rho));
      problem.area.push_back(mesh.area(e));
    }
  }
  Rgb exact(double rho) const { return Rgb(1.0, 0.5, 2.0) / (1 - rho); }
};

double worstRelativeError(const std::vector<Rgb>& b, const Rgb& exact) {
  double worst = 0;
  for (const Rgb& v : b)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(v[c])) return INFINITY;
      worst = std::max(worst, std::fabs(v[c] - exact[c]) / exact[c]);
    }
  return worst;
}

// Runs to the tolerance or the budget; returns whether it got there.
bool run(Solver& solver, double tolerance, int budget) {
  while (solver.progress() > tolerance && solver.iterations() < budget) solver.step();
  return solver.progress() <= tolerance;
}

// rho = 1 exactly (accepted, with a warning): a closed box absorbs nothing, so every shot hands
// all its power on. The unshot power can never fall (the rows of a closed box sum to 1), so the
// solve cannot converge and must stop at its budget, with B finite and the ambient term finite.
TEST(WhiteFurnace, ShootingKeepsAllThePowerUnshotAndStaysFinite) {
  NearlyWhiteFurnace f(1.0);
  ProgressiveSolver solver(f.problem, f.cache);
  EXPECT_FALSE(run(solver, 1e-4, 3000));
  EXPECT_NEAR(solver.progress(), 1.0, 1e-9);  // no power lost, none created
  for (const std::vector<Rgb>& b : {solver.solution(), solver.withAmbient()})
    for (const Rgb& v : b) ASSERT_TRUE(v.isFinite());
}

class HighReflectance : public ::testing::TestWithParam<double> {};

TEST_P(HighReflectance, GaussSeidelReachesEOverOneMinusRho) {
  const double rho = GetParam();
  NearlyWhiteFurnace f(rho);
  GaussSeidelSolver solver(f.problem, gatherMatrix(f.problem, f.cache));
  // The error is at most residual / (1 − rho): stop at 1e-4 (1 − rho) for a 1e-4 error.
  ASSERT_TRUE(run(solver, 1e-4 * (1 - rho), 200000)) << "stuck at residual " << solver.progress();
  const double error = worstRelativeError(solver.solution(), f.exact(rho));
  std::cout << "gauss-seidel rho " << rho << ": " << solver.iterations()
            << " sweeps, max relative error " << error << "\n";
  RecordProperty("sweeps", solver.iterations());
  EXPECT_LT(error, 1e-3);
}

TEST_P(HighReflectance, SouthwellShootingReachesEOverOneMinusRho) {
  const double rho = GetParam();
  NearlyWhiteFurnace f(rho);
  const SparseRows rows = gatherMatrix(f.problem, f.cache);
  GatheringColumns columns(f.problem, rows);
  ProgressiveSolver solver(f.problem, columns);
  // Missing radiosity is rho × the unshot fraction, relative.
  ASSERT_TRUE(run(solver, 1e-4, 50000000)) << "stuck at unshot fraction " << solver.progress();
  const double error = worstRelativeError(solver.solution(), f.exact(rho));
  std::cout << "southwell rho " << rho << ": " << solver.iterations()
            << " shots, max relative error " << error << "\n";
  RecordProperty("shots", solver.iterations());
  EXPECT_LT(error, 1e-3);
}

// Lazy shooting (each element through its own row) solves the system with F_ji replaced by
// A_i F_ij / A_j: per element it differs by the rows' reciprocity noise, amplified near rho = 1,
// but the power it moves is exact, so the area-weighted mean must be E/(1−rho) up to rho × the
// unshot fraction.
TEST_P(HighReflectance, LazyShootingConservesThePowerOfEOverOneMinusRho) {
  const double rho = GetParam();
  NearlyWhiteFurnace f(rho);
  ProgressiveSolver solver(f.problem, f.cache);
  ASSERT_TRUE(run(solver, 1e-4, 50000000)) << "stuck at unshot fraction " << solver.progress();
  Rgb power;
  double area = 0;
  for (int i = 0; i < f.problem.size(); ++i) {
    power += solver.solution()[i] * f.problem.area[i];
    area += f.problem.area[i];
  }
  const double error = worstRelativeError({power / area}, f.exact(rho));
  std::cout << "progressive rho " << rho << ": " << solver.iterations()
            << " shots, mean relative error " << error << ", worst element "
            << worstRelativeError(solver.solution(), f.exact(rho)) << "\n";
  RecordProperty("shots", solver.iterations());
  EXPECT_LT(error, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(NearOne, HighReflectance, ::testing::Values(0.99, 0.999));

}  // namespace
}  // namespace rad
