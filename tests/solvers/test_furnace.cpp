// Furnace tests (../shared/REFERENCES.md): a closed box with uniform reflectance and emission
// has B = E/(1−rho) exactly, whatever the form factors, because every row sums to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

struct Furnace {
  PatchMesh mesh = testing::closedCube(0.02);
  RayCaster rays{mesh};
  HemisphereFormFactors method{mesh, rays, {128, 3}};
  FormFactorCache cache{method};
  RadiosityProblem problem;

  Furnace(double rho, Rgb emission) {
    for (int e = 0; e < mesh.elementCount(); ++e) {
      problem.emission.push_back(emission);
      problem.reflectance.push_back(Rgb::all(rho));
      problem.area.push_back(mesh.area(e));
    }
  }
};

double maxRelativeError(const std::vector<Rgb>& b, const Rgb& exact) {
  double worst = 0;
  for (const Rgb& v : b)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(v[c] - exact[c]) / exact[c]);
  return worst;
}

class LazyProgressiveFurnace : public ::testing::TestWithParam<double> {};

class FurnaceTest : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(FurnaceTest, ConvergesToEOverOneMinusRho) {
  const auto [solverName, rho] = GetParam();
  const Rgb e(1.0, 2.0, 0.5);
  Furnace furnace(rho, e);
  std::unique_ptr<Solver> solver;
  double tolerance;
  SparseRows f = gatherMatrix(furnace.problem, furnace.cache);
  GatheringColumns columns(furnace.problem, f);
  if (solverName == "southwell") {
    solver = std::make_unique<ProgressiveSolver>(furnace.problem, columns);
    tolerance = 1e-5;  // missing radiosity = rho × unshot fraction (relative)
  } else {
    if (solverName == "jacobi")
      solver = std::make_unique<JacobiSolver>(furnace.problem, SparseRows(f));
    else
      solver = std::make_unique<GaussSeidelSolver>(furnace.problem, SparseRows(f));
    tolerance = 1e-5 * (1 - rho);  // error <= residual / (1 − rho)
  }
  const int budget = 5000000;
  while (solver->progress() > tolerance && solver->iterations() < budget) solver->step();
  ASSERT_LE(solver->progress(), tolerance) << "did not converge in " << budget << " steps";
  EXPECT_LT(maxRelativeError(solver->solution(), e / (1 - rho)), 1e-4)
      << solverName << " rho " << rho << " after " << solver->iterations() << " iterations";
}

INSTANTIATE_TEST_SUITE_P(AllSolvers, FurnaceTest,
                         ::testing::Combine(::testing::Values("southwell", "gauss-seidel",
                                                              "jacobi"),
                                            ::testing::Values(0.5, 0.9, 0.99)));

// Lazy shooting uses each shooter's own row, so per element it is exact only up to the noise in
// reciprocity; but the total power it distributes is exact, since every row sums to 1.
TEST_P(LazyProgressiveFurnace, ConservesEnergyExactly) {
  const double rho = GetParam();
  Furnace furnace(rho, Rgb::all(1.0));
  ProgressiveSolver solver(furnace.problem, furnace.cache);
  while (solver.progress() > 1e-6 && solver.iterations() < 5000000) solver.step();
  ASSERT_LE(solver.progress(), 1e-6);
  double power = 0, area = 0;
  for (int i = 0; i < furnace.problem.size(); ++i) {
    power += solver.solution()[i].g * furnace.problem.area[i];
    area += furnace.problem.area[i];
  }
  EXPECT_NEAR(power / area * (1 - rho), 1.0, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Reflectances, LazyProgressiveFurnace, ::testing::Values(0.5, 0.9, 0.99));

TEST(Jacobi, EachStepAddsExactlyOneBounce) {
  const double rho = 0.7;
  Furnace furnace(rho, Rgb::all(1.0));
  JacobiSolver jacobi(furnace.problem, gatherMatrix(furnace.problem, furnace.cache));
  for (int k = 0; k <= 12; ++k) {
    const double expected = (1 - std::pow(rho, k + 1)) / (1 - rho);
    EXPECT_LT(maxRelativeError(jacobi.solution(), Rgb::all(expected)), 1e-12) << "bounce " << k;
    jacobi.step();
  }
}

TEST(Progressive, AmbientTermCoversTheUnshotEnergyInAFurnace) {
  // Uniform furnace: total (B + rho·ambient)·A equals the exact total at any point of the solve.
  const double rho = 0.8;
  Furnace furnace(rho, Rgb::all(1.0));
  ProgressiveSolver solver(furnace.problem, furnace.cache);
  for (int k = 0; k < 50; ++k) solver.step();
  double withAmbient = 0, without = 0, area = 0;
  const auto display = solver.withAmbient();
  for (int i = 0; i < furnace.problem.size(); ++i) {
    withAmbient += display[i].r * furnace.problem.area[i];
    without += solver.solution()[i].r * furnace.problem.area[i];
    area += furnace.problem.area[i];
  }
  const double exact = area / (1 - rho);
  EXPECT_GT(std::fabs(without - exact) / exact, 0.05);  // far from converged
  EXPECT_NEAR(withAmbient / exact, 1.0, 1e-9);
}

}  // namespace
}  // namespace rad
