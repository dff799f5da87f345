#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "meshing/patch_mesh.h"
#include "meshing/polygon_triangulation.h"

namespace rad {
namespace {

// Two unit squares meeting at a right angle along x (an L), sharing the edge's two vertices.
PatchMesh makeL() {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                    {0, 1, 0}, {1, 0, 1}, {0, 0, 1}};
  return PatchMesh(p, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 1}});
}

// Point-on-segment test used to detect T-vertices.
bool strictlyInside(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = (p - a).dot(ab) / ab.squaredNorm();
  if (t <= 1e-9 || t >= 1 - 1e-9) return false;
  return (a + t * ab - p).norm() < 1e-9 * ab.norm();
}

void expectConforming(const PatchMesh& mesh) {
  const TriMesh& m = mesh.mesh();
  for (auto e : m.edges()) {
    const int faces =
        !m.is_boundary(m.halfedge_handle(e, 0)) + !m.is_boundary(m.halfedge_handle(e, 1));
    EXPECT_GE(faces, 1);
    EXPECT_LE(faces, 2);
  }
  // No vertex may lie inside another element's edge (a T-vertex).
  for (int v = 0; v < mesh.vertexCount(); ++v)
    for (int e = 0; e < mesh.elementCount(); ++e) {
      const auto c = mesh.corners(e);
      for (int k = 0; k < 3; ++k)
        ASSERT_FALSE(strictlyInside(mesh.position(v), c[k], c[(k + 1) % 3]))
            << "vertex " << v << " is a T-vertex on element " << e;
    }
}

TEST(PatchMesh, KeepsPatchesAndMaterials) {
  const PatchMesh mesh = makeL();
  EXPECT_EQ(mesh.patchCount(), 2);
  EXPECT_EQ(mesh.elementCount(), 4);
  EXPECT_EQ(mesh.inputTriangleCount(), 4);
  EXPECT_NEAR(mesh.totalArea(), 2.0, 1e-15);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    EXPECT_EQ(mesh.material(e), mesh.patch(e));
    // The first square faces +z, the second (wound 1,0,5,4) faces +y.
    const Eigen::Vector3d expected =
        mesh.patch(e) == 0 ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(0, 1, 0);
    EXPECT_NEAR((mesh.normal(e) - expected).norm(), 0, 1e-12);
  }
}

TEST(PatchMesh, UniformSubdivisionIsConformingAndKeepsArea) {
  PatchMesh mesh = makeL();
  mesh.subdivideUniform(0.01);
  EXPECT_GE(mesh.elementCount(), 200);  // 2 m² / 0.01 m²
  EXPECT_NEAR(mesh.totalArea(), 2.0, 2.0 * 1e-9);
  EXPECT_NEAR(mesh.patchArea(0), 1.0, 1e-9);
  double largest = 0, smallest = 1;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    largest = std::max(largest, mesh.area(e));
    smallest = std::min(smallest, mesh.area(e));
  }
  EXPECT_LE(largest, 0.01);
  // Longest-edge bisection of a square's halves gives elements within a factor 2 of each other.
  EXPECT_GE(smallest, 0.01 / 4);
  expectConforming(mesh);
}

TEST(PatchMesh, BisectionAcrossPatchesKeepsSharedEdgeConforming) {
  PatchMesh mesh = makeL();
  for (int round = 0; round < 5; ++round) mesh.bisect(0);
  expectConforming(mesh);
  EXPECT_NEAR(mesh.totalArea(), 2.0, 2e-9);
  for (int e = 0; e < mesh.elementCount(); ++e) EXPECT_LE(mesh.level(e), 64);
}

TEST(PolygonTriangulation, NonConvexPolygonKeepsArea) {
  // An L-shaped hexagon of area 3.
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                    {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  const auto triangles = triangulatePolygon(p);
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0;
  for (const auto& t : triangles) {
    const Eigen::Vector3d n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    EXPECT_GT(n.z(), 0);  // winding kept
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
}

}  // namespace
}  // namespace rad

namespace rad {
namespace {

TEST(PatchMesh, ShootersTileTheSurfaceAndContainTheirElements) {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0}});
  EXPECT_EQ(mesh.shooterCount(), mesh.elementCount());  // unmarked: one shooter per element
  mesh.subdivideUniform(0.25);
  mesh.markShooters();
  const int shooters = mesh.shooterCount();
  mesh.subdivideUniform(0.25 / 8);
  EXPECT_EQ(mesh.shooterCount(), shooters);
  EXPECT_GT(mesh.elementCount(), 4 * shooters);
  std::vector<double> covered(shooters, 0);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const int s = mesh.shooter(e);
    covered[s] += mesh.area(e);
    // The element's centroid lies inside its shooter's triangle (barycentric test).
    const auto c = mesh.shooterCorners(s);
    const Eigen::Vector3d q = mesh.centroid(e);
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
    for (int k = 0; k < 3; ++k) EXPECT_GE((c[(k + 1) % 3] - c[k]).cross(q - c[k]).dot(n), -1e-12);
  }
  double total = 0;
  for (int s = 0; s < shooters; ++s) {
    EXPECT_NEAR(covered[s], mesh.shooterArea(s), 1e-12);
    total += mesh.shooterArea(s);
  }
  EXPECT_NEAR(total, 2.0, 1e-12);
}

}  // namespace
}  // namespace rad
