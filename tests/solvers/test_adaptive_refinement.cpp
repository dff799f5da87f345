// Adaptive refinement on the Cornell box: conforming, concentrated at shadow boundaries, and
// incremental (the continued solve equals a fresh solve on the refined mesh).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "radiosity/core/log.h"
#include "radiosity/formfactors/analytic_patch_shots.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

class AdaptiveCornell : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Scene scene = loadObjScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj");
    SolveOptions options;
    options.formFactors = FormFactorMethod::Analytic;
    // An area bound, not an element count: every wall starts at one density (a count stops
    // part-way through a level of bisection, leaving some walls twice as fine as others), so
    // the densities below measure refinement alone.
    options.maxArea = buildPatchMesh(scene).totalArea() / 400;
    options.refineThreshold = 0.5;
    options.refinePasses = 3;
    options.shadowRays = 16;
    options.tolerance = 1e-5;
    setLogLevel(LogLevel::Quiet);
    result_ = new SolveResult(solveScene(scene, options));
  }
  static void TearDownTestSuite() { delete result_; }
  static inline SolveResult* result_;
};

bool strictlyInside(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = (p - a).dot(ab) / ab.squaredNorm();
  if (t <= 1e-9 || t >= 1 - 1e-9) return false;
  return (a + t * ab - p).norm() < 1e-9 * ab.norm();
}

TEST_F(AdaptiveCornell, RefinedMeshIsConformingAndKeepsTheArea) {
  const PatchMesh& mesh = *result_->solution.mesh;
  ASSERT_GT(result_->report.refinementPasses, 0);
  ASSERT_GT(mesh.elementCount(), result_->report.elementsBeforeRefinement);
  const TriMesh& m = mesh.mesh();
  for (auto e : m.edges()) {
    const int faces =
        !m.is_boundary(m.halfedge_handle(e, 0)) + !m.is_boundary(m.halfedge_handle(e, 1));
    ASSERT_GE(faces, 1);
    ASSERT_LE(faces, 2);
  }
  // No vertex inside another element's edge, within each connected surface (the OBJ's objects
  // share no vertices with each other, so where two of them touch, like a wall and the floor,
  // their edges are independent by construction).
  std::vector<int> component(mesh.vertexCount(), -1);
  for (int start = 0; start < mesh.vertexCount(); ++start) {
    if (component[start] >= 0) continue;
    std::vector<int> stack = {start};
    component[start] = start;
    while (!stack.empty()) {
      const auto vh = TriMesh::VertexHandle(stack.back());
      stack.pop_back();
      for (auto w : m.vv_range(vh))
        if (component[w.idx()] < 0) {
          component[w.idx()] = start;
          stack.push_back(w.idx());
        }
    }
  }
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto c = mesh.corners(e);
    const int surface = component[mesh.cornerVertices(e)[0]];
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      if (component[v] != surface) continue;
      for (int k = 0; k < 3; ++k)
        ASSERT_FALSE(strictlyInside(mesh.position(v), c[k], c[(k + 1) % 3])) << "T-vertex " << v;
    }
  }
  const Scene& scene = result_->solution.scene;
  const PatchMesh input = PatchMesh(scene.positions, [&] {
    std::vector<PatchPolygon> p;
    for (const auto& polygon : scene.polygons) p.push_back({polygon.vertices, polygon.material});
    return p;
  }());
  EXPECT_NEAR(mesh.totalArea(), input.totalArea(), 1e-9 * input.totalArea());
}

// Elements per unit area of the elements whose centroid satisfies `where`.
template <class Where>
double density(const PatchMesh& mesh, Where where) {
  double area = 0;
  int count = 0;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (where(e, mesh.centroid(e))) {
      area += mesh.area(e);
      ++count;
    }
  return area > 0 ? count / area : 0;
}

TEST_F(AdaptiveCornell, ElementsGoToShadowBoundariesNotToUniformlyLitWalls) {
  const PatchMesh& mesh = *result_->solution.mesh;
  const double uniform = result_->report.elementsBeforeRefinement / mesh.totalArea();
  // A band on the floor around the short block's footprint (x 0.08–0.29, z 0.07–0.27): its
  // contact shadow and penumbra.
  const double band = density(mesh, [&](int e, const Eigen::Vector3d& c) {
    const bool floor = mesh.normal(e).y() > 0.99 && c.y() < 1e-6;
    const bool near = c.x() > 0.03 && c.x() < 0.34 && c.z() > 0.02 && c.z() < 0.32;
    const bool under = c.x() > 0.13 && c.x() < 0.24 && c.z() > 0.12 && c.z() < 0.22;
    return floor && near && !under;
  });
  // The green wall (x = 0): nothing casts a shadow on it.
  const double greenWall = density(mesh, [&](int e, const Eigen::Vector3d& c) {
    return mesh.normal(e).x() > 0.99 && c.x() < 1e-6;
  });
  EXPECT_GT(band, 4 * uniform) << "band " << band << " uniform " << uniform;
  EXPECT_LT(greenWall, 1.25 * uniform) << "green wall " << greenWall << " uniform " << uniform;
}

TEST_F(AdaptiveCornell, ContinuedSolveEqualsAFreshSolveOnTheRefinedMesh) {
  // Same mesh, same shooters, same deterministic form factors: only the history differs.
  const PatchMesh& mesh = *result_->solution.mesh;
  RayCaster rays(mesh);
  AnalyticPatchShots shots(mesh, rays, {3, 16, 1});
  ProgressiveSolver fresh(result_->solution.problem, shots);
  while (fresh.progress() > 1e-5) fresh.step();
  std::vector<Rgb> difference(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    difference[e] = fresh.solution()[e] - result_->solution.radiosity[e];
  // Both stopped with at most 1e-5 of the power unshot; what that can still change is
  // rho/(1 − rho) of it, below 3e-5 for rho <= 0.725.
  EXPECT_LT(relativeToEmission(result_->solution.problem, difference), 1e-4);
  // The same for the values at the receiver points, which the refinement carried over and
  // re-gathered for the changed elements.
  ASSERT_EQ(result_->solution.pointRadiosity.size(), static_cast<size_t>(mesh.elementCount()));
  for (int k = 0; k < 3; ++k) {
    for (int e = 0; e < mesh.elementCount(); ++e)
      difference[e] = fresh.pointSolution()[e][k] - result_->solution.pointRadiosity[e][k];
    EXPECT_LT(relativeToEmission(result_->solution.problem, difference), 1e-4) << "point " << k;
  }
}

TEST_F(AdaptiveCornell, ReceiverPointValuesAverageToTheElementValues) {
  // Each element's value is the mean of its point factors' contributions; the points are kept in
  // single precision, so the means agree to about 1e-6 of the value.
  const PatchMesh& mesh = *result_->solution.mesh;
  ASSERT_EQ(result_->solution.pointRadiosity.size(), static_cast<size_t>(mesh.elementCount()));
  bool someVary = false;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto& p = result_->solution.pointRadiosity[e];
    const Rgb mean = (p[0] + p[1] + p[2]) / 3.0;
    const Rgb& b = result_->solution.radiosity[e];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], b[c], 1e-5 * b[c] + 1e-12) << "element " << e;
    someVary |= std::fabs(p[0].r - p[1].r) > 1e-3 * b.r;
  }
  EXPECT_TRUE(someVary);  // the points resolve the field inside the elements
}

}  // namespace
}  // namespace rad
