// traceRow() must cast exactly the rays computeRow() counts: the viewer draws them as the row.
#include <gtest/gtest.h>

#include <map>

#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

TEST(RowRays, CountTheSameHitsAsTheRow) {
  const PatchMesh mesh = testing::closedCube(0.05);
  const RayCaster caster(mesh);
  std::vector<int> multiplier(mesh.elementCount(), 1);
  multiplier[3] = 3;  // an emitter-like row with more rays
  const HemisphereFormFactors method(mesh, caster, {100, 7, multiplier});
  for (int e : {0, 3, mesh.elementCount() - 1}) {
    const FormFactorRow row = method.computeRow(e);
    const std::vector<RowRay> rays = method.traceRow(e);
    ASSERT_EQ(static_cast<int>(rays.size()), method.raysForRow(e));
    std::map<int, int> hits;
    int escaped = 0;
    for (const RowRay& r : rays) {
      if (r.target >= 0)
        ++hits[r.target];
      else
        ++escaped;
    }
    EXPECT_DOUBLE_EQ(row.escaped, static_cast<double>(escaped) / rays.size());
    ASSERT_EQ(row.targets.size(), hits.size()) << "element " << e;
    for (size_t k = 0; k < row.targets.size(); ++k) {
      EXPECT_DOUBLE_EQ(row.values[k], static_cast<double>(hits[row.targets[k]]) / rays.size());
    }
  }
}

TEST(RowRays, LeaveTheFrontAndEndOnWhatTheyHit) {
  const PatchMesh mesh = testing::closedCube(0.1);
  const RayCaster caster(mesh);
  const HemisphereFormFactors method(mesh, caster, {64, 1});
  const int e = 5;
  const Eigen::Vector3d n = mesh.normal(e);
  const auto c = mesh.corners(e);
  for (const RowRay& r : method.traceRow(e)) {
    EXPECT_NEAR(r.direction.norm(), 1.0, 1e-12);
    EXPECT_GT(r.direction.dot(n), 0.0);
    // The origin lies on the element's plane, lifted by the ray offset only.
    EXPECT_NEAR((r.origin - c[0]).dot(n), caster.surfaceOffset(), 1e-9);
    // A closed cube: every ray lands on the front of another element, on that element's plane.
    ASSERT_GE(r.target, 0);
    const Eigen::Vector3d end = r.origin + r.distance * r.direction;
    EXPECT_NEAR((end - mesh.corners(r.target)[0]).dot(mesh.normal(r.target)), 0.0, 1e-5);
  }
}

}  // namespace
}  // namespace rad
