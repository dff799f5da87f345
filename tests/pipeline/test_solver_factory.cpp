// The one solver factory: every kind builds, converges to the same solution of a small closed
// system with an exact answer, and the gathering matrix is built only for the solvers that need
// it.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/core/errors.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/refinable_solver.h"
#include "radiosity/solvers/solver_factory.h"

namespace rad {
namespace {

// Two elements of equal area that see only each other: F_01 = F_10 = 1. With E = (1, 0) and
// rho = 0.5 the system B0 = 1 + B1/2, B1 = B0/2 gives B0 = 4/3, B1 = 2/3.
struct TwoPlates : ShotRows {
  RadiosityProblem problem;
  FormFactorRow rows[2];
  TwoPlates() {
    problem.emission = {Rgb::all(1), Rgb()};
    problem.reflectance = {Rgb::all(0.5), Rgb::all(0.5)};
    problem.area = {1, 1};
    rows[0].targets = {1};
    rows[0].values = {1.0};
    rows[1].targets = {0};
    rows[1].values = {1.0};
  }
  int shooterCount() const override { return 2; }
  int shooterOf(int element) const override { return element; }
  double shooterArea(int) const override { return 1; }
  const FormFactorRow& powerFractions(int shooter) override { return rows[shooter]; }
  std::string description() const override { return "two plates"; }
  SparseRows matrix() const {
    SparseRows f(2, 2);
    f.insert(0, 1) = 1;
    f.insert(1, 0) = 1;
    f.makeCompressed();
    return f;
  }
};

TEST(SolverFactory, EveryKindSolvesTheTwoPlateSystem) {
  for (SolverKind kind : {SolverKind::Progressive, SolverKind::Southwell, SolverKind::GaussSeidel,
                          SolverKind::Jacobi}) {
    TwoPlates plates;
    int matrixBuilds = 0;
    auto solver = makeSolver(kind, plates.problem, plates, [&] {
      ++matrixBuilds;
      return plates.matrix();
    });
    ASSERT_NE(solver, nullptr);
    EXPECT_EQ(solver->name(), solverKindName(kind));
    EXPECT_EQ(matrixBuilds, needsGatheringMatrix(kind) ? 1 : 0) << solverKindName(kind);
    while (solver->progress() > 1e-12 && solver->iterations() < 1000) solver->step();
    EXPECT_NEAR(solver->solution()[0].r, 4.0 / 3.0, 1e-9) << solverKindName(kind);
    EXPECT_NEAR(solver->solution()[1].g, 2.0 / 3.0, 1e-9) << solverKindName(kind);
  }
}

TEST(SolverFactory, ShootingSolversAreRefinable) {
  TwoPlates plates;
  const auto matrix = [&] { return plates.matrix(); };
  EXPECT_NE(dynamic_cast<RefinableSolver*>(
                makeSolver(SolverKind::Progressive, plates.problem, plates, matrix).get()),
            nullptr);
  EXPECT_EQ(dynamic_cast<RefinableSolver*>(
                makeSolver(SolverKind::GaussSeidel, plates.problem, plates, matrix).get()),
            nullptr);
}

TEST(SolverFactory, NamesRoundTripAndUnknownNamesAreRefused) {
  for (SolverKind kind : {SolverKind::Progressive, SolverKind::Southwell, SolverKind::GaussSeidel,
                          SolverKind::Jacobi})
    EXPECT_EQ(parseSolverKind(solverKindName(kind)), kind);
  EXPECT_THROW(parseSolverKind("conjugate-gradient"), InputError);
}

}  // namespace
}  // namespace rad
