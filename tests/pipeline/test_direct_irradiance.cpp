// Solution::directIrradiance, each element's E_d as the solve computed it: the emitters' part is
// the solver's own first bounce (exactly, for Jacobi's), the lights' part their first shot, every
// solver agrees with the analytic form factor, and B = ρ E_d where nothing else lights a surface.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/solvers/solver_factory.h"
#include "tests/support/test_scenes.h"

namespace rad {
namespace {

const std::string kSquares = std::string(RADIOSITY_DATA_DIR) + "/tests/parallel_squares.obj";
const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

SolveOptions options(SolverKind solver, int elements = 128, int rays = 256) {
  SolveOptions o;
  o.solver = solver;
  o.targetElements = elements;
  o.raysPerElement = rays;
  o.threads = 2;
  return o;
}

// One Jacobi bounce is B_1 = E + ρ F E, and E_d = F E by the same rows: B − E − ρ E_d vanishes
// up to the rounding of one product per element.
TEST(DirectIrradiance, OneJacobiBounceIsTheEmittersDirectLightExactly) {
  SolveOptions o = options(SolverKind::Jacobi, 300);
  o.bounces = 1;
  const SolveResult r = solveScene(loadScene(kCornell), o);
  const Solution& s = r.solution;
  ASSERT_EQ(s.directIrradiance.size(), s.radiosity.size());
  double largest = 0;
  for (const Rgb& b : s.radiosity) largest = std::max(largest, b.maxComponent());
  int lit = 0;
  for (size_t e = 0; e < s.radiosity.size(); ++e) {
    const Rgb rest =
        s.radiosity[e] - s.problem.emission[e] - s.problem.reflectance[e] * s.directIrradiance[e];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(rest[c], 0.0, 1e-12 * largest) << e;
    lit += s.directIrradiance[e].maxComponent() > 0;
  }
  EXPECT_GT(lit, static_cast<int>(s.radiosity.size()) / 3);  // the walls and floor see the lamp
}

// Two opposed unit squares at distance 1 (REFERENCES.md): the receiver's mean E_d is
// π Ke F = π · 0.199825, whatever the solver. Hemisphere rows: the receiver's (or the emitter's)
// ≥ 128 × 256 rays estimate F within σ = √(F(1 − F)/32768) = 0.0022; the hierarchical solve's
// shadow rays to the emitter with closed-form factors, tighter still. 4σ = 0.0089 of F.
TEST(DirectIrradiance, EverySolverGivesTheParallelSquaresFormFactor) {
  const double expected = M_PI * 0.199825, bound = M_PI * 4 * std::sqrt(0.2 * 0.8 / 32768);
  for (const SolverKind solver : {SolverKind::GaussSeidel, SolverKind::Jacobi,
                                  SolverKind::Progressive, SolverKind::Hierarchical}) {
    const SolveResult r = solveScene(loadScene(kSquares), options(solver, 256));
    const Solution& s = r.solution;
    ASSERT_EQ(s.directIrradiance.size(), s.radiosity.size());
    double area = 0, sum = 0;
    for (int e = 0; e < s.mesh->elementCount(); ++e) {
      if (s.problem.reflectance[e].maxComponent() == 0) {
        EXPECT_TRUE(s.directIrradiance[e].isZero());  // the black source: nothing to pass on
        continue;
      }
      area += s.mesh->area(e);
      sum += s.mesh->area(e) * s.directIrradiance[e].g;
    }
    EXPECT_NEAR(sum / area, expected, bound) << solverKindName(solver);
  }
}

// An open floor under a sun and a sky sees no other surface: B = ρ E_d there, for every solver,
// E_d being the lights' first shot the solve added.
TEST(DirectIrradiance, OnAnOpenFloorUnderTheSkyBIsRhoTimesEd) {
  const Rgb rho{0.5, 0.4, 0.3};
  Scene scene = testing::greyScene(
      rho,
      {skyLight({0.2, 0.3, 0.4}), sunLight(Eigen::Vector3d(0.3, -1, 0.2).normalized(), {3, 2, 1})});
  testing::addPolygon(scene, {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}});
  for (const SolverKind solver :
       {SolverKind::GaussSeidel, SolverKind::Progressive, SolverKind::Hierarchical}) {
    const SolveResult r = solveScene(scene, options(solver, 64, 64));
    const Solution& s = r.solution;
    ASSERT_EQ(s.directIrradiance.size(), s.radiosity.size());
    for (size_t e = 0; e < s.radiosity.size(); ++e) {
      const Rgb expected = rho * s.directIrradiance[e];
      EXPECT_GT(s.directIrradiance[e].r, 3.0 * 0.9);  // the sun's E cosθ and the sky's πL
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s.radiosity[e][c], expected[c], 1e-12 * expected[c]) << solverKindName(solver);
    }
  }
}

}  // namespace
}  // namespace rad
