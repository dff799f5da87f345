#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "tests/support/analytic_form_factors.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

// Patch-to-patch estimate from element rows: F_PQ = sum over elements e of P (A_e/A_P) F_eQ.
double patchFormFactor(const PatchMesh& mesh, FormFactorCache& cache, int from, int to) {
  double sum = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.patch(e) != from) continue;
    const FormFactorRow& row = cache.row(e);
    double toPatch = 0;
    for (size_t k = 0; k < row.targets.size(); ++k)
      if (mesh.patch(row.targets[k]) == to) toPatch += row.values[k];
    sum += mesh.area(e) * toPatch;
  }
  return sum / mesh.patchArea(from);
}

// Binomial standard deviation of a hit fraction p over n rays. Stratification only lowers the
// real spread, so 4σ of this bound is a safe tolerance.
double sigma(double p, double rays) { return std::sqrt(p * (1 - p) / rays); }

// Raises the rays of every element of a patch so n elements × rays is the sample count.
int raysOnPatch(const PatchMesh& mesh, int patch, int perElement) {
  int elements = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) elements += mesh.patch(e) == patch;
  return elements * perElement;
}

// The rows' azimuth comes from turnCosSin's polynomials instead of std::sincos: they must agree
// to float precision over the whole turn (the quarter-turn reduction included), so the directions
// keep the cosine-weighted distribution.
TEST(HemisphereSampling, TurnCosSinMatchesTheLibraryToFloatPrecision) {
  double worst = 0, worstLength = 0;
  const int steps = 1 << 20;
  for (int k = 0; k <= steps; ++k) {
    const float u = static_cast<float>(k) / steps;
    float c, s;
    turnCosSin(u, c, s);
    const double phi = 2.0 * M_PI * u;
    worst = std::max({worst, std::abs(c - std::cos(phi)), std::abs(s - std::sin(phi))});
    worstLength = std::max(worstLength, std::abs(double(c) * c + double(s) * s - 1.0));
  }
  // A few float ulps of 1 (6e-8 each): the reduction's rounding plus the polynomials' error.
  EXPECT_LT(worst, 4e-7);
  EXPECT_LT(worstLength, 1e-6);
}

TEST(HemisphereFormFactors, ParallelUnitSquaresMatchHowell) {
  // z = 0 facing +z, z = 1 facing −z.
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 1}});
  mesh.subdivideUniform(0.05);
  RayCaster rays(mesh);
  HemisphereFormFactors method(mesh, rays, {4096, 7});
  FormFactorCache cache(method);
  const double exact = reference::parallelRectangles(1, 1, 1);
  ASSERT_NEAR(exact, 0.199825, 1e-6);
  const double estimate = patchFormFactor(mesh, cache, 0, 1);
  EXPECT_NEAR(estimate, exact, 4 * sigma(exact, raysOnPatch(mesh, 0, 4096)));
  // The reverse direction estimates the same number (equal areas: reciprocity).
  EXPECT_NEAR(patchFormFactor(mesh, cache, 1, 0), exact,
              4 * sigma(exact, raysOnPatch(mesh, 1, 4096)));
}

// Rectangle 1 (1×w, in the plane z = 0, facing +z) and rectangle 2 (1×h, plane y = 0, facing +y)
// share the edge along x.
PatchMesh perpendicular(double w, double h) {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, w, 0},
                                    {0, w, 0}, {1, 0, h}, {0, 0, h}};
  return PatchMesh(p, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 1}});
}

TEST(HemisphereFormFactors, PerpendicularUnitSquaresMatchHowell) {
  PatchMesh mesh = perpendicular(1, 1);
  mesh.subdivideUniform(0.05);
  RayCaster rays(mesh);
  HemisphereFormFactors method(mesh, rays, {4096, 11});
  FormFactorCache cache(method);
  const double exact = reference::perpendicularRectangles(1, 1, 1);
  ASSERT_NEAR(exact, 0.200044, 1e-6);
  EXPECT_NEAR(patchFormFactor(mesh, cache, 0, 1), exact,
              4 * sigma(exact, raysOnPatch(mesh, 0, 4096)));
}

TEST(HemisphereFormFactors, ReciprocityOfUnequalPerpendicularRectangles) {
  // A1 = 2, A2 = 0.5: A1 F12 = A2 F21 although F12 and F21 differ by a factor 4.
  PatchMesh mesh = perpendicular(2, 0.5);
  mesh.subdivideUniform(0.05);
  RayCaster rays(mesh);
  HemisphereFormFactors method(mesh, rays, {2048, 3});
  FormFactorCache cache(method);
  const double f12 = reference::perpendicularRectangles(1, 2, 0.5);
  const double f21 = reference::perpendicularRectangles(1, 0.5, 2);
  ASSERT_NEAR(2 * f12, 0.5 * f21, 1e-12);  // the analytic values themselves are reciprocal
  const double a1f12 = 2 * patchFormFactor(mesh, cache, 0, 1);
  const double a2f21 = 0.5 * patchFormFactor(mesh, cache, 1, 0);
  const double tolerance = 4 * std::hypot(2 * sigma(f12, raysOnPatch(mesh, 0, 2048)),
                                          0.5 * sigma(f21, raysOnPatch(mesh, 1, 2048)));
  EXPECT_NEAR(a1f12, a2f21, tolerance);
  EXPECT_NEAR(a1f12, 2 * f12, 4 * 2 * sigma(f12, raysOnPatch(mesh, 0, 2048)));
}

TEST(HemisphereFormFactors, RowsOfAClosedBoxSumToOne) {
  PatchMesh mesh = testing::closedCube(0.02);
  RayCaster rays(mesh);
  HemisphereFormFactors method(mesh, rays, {256, 5});
  FormFactorCache cache(method);
  cache.computeRows(std::vector<bool>(mesh.elementCount(), true));
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const FormFactorRow& row = cache.row(e);
    ASSERT_EQ(row.escaped, 0.0) << "element " << e << " lost rays";
    ASSERT_NEAR(row.sum(), 1.0, 1e-12);
    EXPECT_EQ(row.valueFor(e), 0.0);  // a planar element cannot see itself
  }
}

TEST(HemisphereFormFactors, RowDoesNotDependOnThreadsOrOrder) {
  PatchMesh mesh = testing::closedCube(0.05);
  RayCaster rays(mesh);
  HemisphereFormFactors method(mesh, rays, {500, 99});
  FormFactorCache all(method);
  all.computeRows(std::vector<bool>(mesh.elementCount(), true));
  FormFactorRow single;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    single = method.computeRow(17);
  }
  EXPECT_EQ(single.targets, all.row(17).targets);
  EXPECT_EQ(single.values, all.row(17).values);
  // A different seed gives a different (but equally valid) estimate.
  HemisphereFormFactors other(mesh, rays, {500, 100});
  EXPECT_NE(other.computeRow(17).values, single.values);
}

}  // namespace
}  // namespace rad
