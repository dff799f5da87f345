// Element counts and shapes: subdivideToCount meets a requested count within 20% with sizes
// close to uniform, and splitSlivers turns thin strips into elements under the aspect bound,
// conforming and keeping area and texture coordinates.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "meshing/patch_mesh.h"

namespace rad {
namespace {

bool strictlyInside(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = (p - a).dot(ab) / ab.squaredNorm();
  if (t <= 1e-9 || t >= 1 - 1e-9) return false;
  return (a + t * ab - p).norm() < 1e-9 * ab.norm();
}

// Every edge between one and two faces, and no vertex inside another element's edge.
void expectConforming(const PatchMesh& mesh) {
  const TriMesh& m = mesh.mesh();
  for (auto e : m.edges()) {
    const int faces =
        !m.is_boundary(m.halfedge_handle(e, 0)) + !m.is_boundary(m.halfedge_handle(e, 1));
    ASSERT_GE(faces, 1);
    ASSERT_LE(faces, 2);
  }
  for (int v = 0; v < mesh.vertexCount(); ++v)
    for (int e = 0; e < mesh.elementCount(); ++e) {
      const auto c = mesh.corners(e);
      for (int k = 0; k < 3; ++k)
        ASSERT_FALSE(strictlyInside(mesh.position(v), c[k], c[(k + 1) % 3]))
            << "vertex " << v << " is a T-vertex on element " << e;
    }
}

// A w × h rectangle in the z = 0 plane at x0, as one quad polygon, with UVs (x, y) / 7.
void addRectangle(std::vector<Eigen::Vector3d>& p, std::vector<PatchPolygon>& polygons, double x0,
                  double y0, double w, double h, int material = 0) {
  const int base = static_cast<int>(p.size());
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}})
    p.push_back({x, y, 0});
  std::vector<Eigen::Vector2d> uvs;
  for (int k = 0; k < 4; ++k) uvs.push_back(p[base + k].head<2>() / 7);
  polygons.push_back({{base, base + 1, base + 2, base + 3}, material, uvs});
}

PatchMesh rectangle(double w, double h) {
  std::vector<Eigen::Vector3d> p;
  std::vector<PatchPolygon> polygons;
  addRectangle(p, polygons, 0, 0, w, h);
  return PatchMesh(p, polygons);
}

// An n × n grid of unit squares sharing their corners, each its own polygon (a scene of many
// small triangles).
PatchMesh grid(int n) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) p.push_back({double(i), double(j), 0});
  const auto at = [n](int i, int j) { return i * (n + 1) + j; };
  std::vector<PatchPolygon> polygons;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      polygons.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, 0});
  return PatchMesh(p, polygons);
}

void expectCountMet(PatchMesh mesh, int count) {
  const double total = mesh.totalArea();
  mesh.subdivideToCount(count);
  EXPECT_GE(mesh.elementCount(), count);
  EXPECT_LE(mesh.elementCount(), 1.2 * count);
  EXPECT_NEAR(mesh.totalArea(), total, 1e-9 * total);
  double largest = 0, smallest = total;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    largest = std::max(largest, mesh.area(e));
    smallest = std::min(smallest, mesh.area(e));
  }
  // Largest first: nothing is split while an element twice its size remains, and a split's
  // neighbours (conformity) are at most halved once more.
  EXPECT_LE(largest / smallest, 4.0) << count << " elements";
  expectConforming(mesh);
}

TEST(SubdivideToCount, MeetsTheCountOnASquare) {
  for (int count : {7, 50, 333, 1000}) expectCountMet(rectangle(1, 1), count);
}

TEST(SubdivideToCount, MeetsTheCountOnALongThinQuad) {
  for (int count : {40, 500}) expectCountMet(rectangle(20, 0.5), count);
}

TEST(SubdivideToCount, MeetsTheCountOnManySmallTriangles) {
  // 800 input triangles of one area: the count grows from there.
  for (int count : {900, 2000, 5000}) expectCountMet(grid(20), count);
}

TEST(SubdivideToCount, KeepsAMeshAlreadyLargeEnough) {
  PatchMesh mesh = grid(5);
  mesh.subdivideToCount(10);
  EXPECT_EQ(mesh.elementCount(), 50);
}

double worstAspect(const PatchMesh& mesh) {
  double worst = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) worst = std::max(worst, mesh.aspectRatio(e));
  return worst;
}

TEST(AspectRatio, OfKnownTriangles) {
  // The halves of a square: hypotenuse √2 over altitude 1/√2.
  const PatchMesh square = rectangle(1, 1);
  for (int e = 0; e < square.elementCount(); ++e) EXPECT_NEAR(square.aspectRatio(e), 2, 1e-12);
  // Halves of a 10 × 0.1 strip: (100 + 0.01) / (10 · 0.1).
  const PatchMesh strip = rectangle(10, 0.1);
  for (int e = 0; e < strip.elementCount(); ++e) EXPECT_NEAR(strip.aspectRatio(e), 100.01, 1e-9);
}

TEST(SplitSlivers, AThinStripBecomesWellShapedElements) {
  PatchMesh mesh = rectangle(10, 0.1);
  mesh.splitSlivers(4, 0);
  EXPECT_LE(worstAspect(mesh), 4.0);
  // Well-shaped pieces of a 0.1-wide strip are about 0.1 long: at least 10 / 0.1 · 2 / 4 of
  // them, and not wildly more.
  EXPECT_GE(mesh.elementCount(), 50);
  EXPECT_LE(mesh.elementCount(), 800);
  EXPECT_NEAR(mesh.totalArea(), 1.0, 1e-9);
  expectConforming(mesh);
}

TEST(SplitSlivers, KeepsTheNeighbourConforming) {
  // A 4 × 0.05 strip along the edge of a 4 × 4 square, sharing its corner vertices: the
  // strip's long edge is split, so the square's triangles along it are split too. The strip's
  // elements meet the bound; the square's fan towards the new vertices is left to the size
  // subdivision (its triangles have no outline edge as long as their longest).
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {4, 0, 0},     {4, 4, 0},
                                    {0, 4, 0}, {4, -0.05, 0}, {0, -0.05, 0}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0}, {{5, 4, 1, 0}, 1}});
  mesh.splitSlivers(4, 0);
  int stripElements = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    EXPECT_EQ(mesh.material(e), mesh.patch(e));
    if (mesh.patch(e) != 1) continue;
    EXPECT_LE(mesh.aspectRatio(e), 4.0) << "element " << e;
    ++stripElements;
  }
  EXPECT_GE(stripElements, 4 / 0.05 / 2);
  EXPECT_NEAR(mesh.patchArea(0), 16, 1e-9);
  EXPECT_NEAR(mesh.patchArea(1), 0.2, 1e-9);
  expectConforming(mesh);
}

TEST(SplitSlivers, StopsAtTheSmallestEdge) {
  // Below the smallest edge a strip stays thin, but no element is longer than that edge.
  PatchMesh mesh = rectangle(10, 0.01);
  mesh.splitSlivers(4, 0.5);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto c = mesh.corners(e);
    for (int k = 0; k < 3; ++k) EXPECT_LE((c[k] - c[(k + 1) % 3]).norm(), 0.5 + 1e-9);
  }
  expectConforming(mesh);
}

TEST(SplitSlivers, LeavesWellShapedElementsAlone) {
  PatchMesh mesh = grid(3);
  mesh.splitSlivers(4, 0);
  EXPECT_EQ(mesh.elementCount(), 18);
}

TEST(SplitSlivers, KeepsTheTextureCoordinatesOfEveryCorner) {
  // The rectangle's UVs are (x, y) / 7: after bisections and flips every element's corners
  // must still carry exactly that.
  PatchMesh mesh = rectangle(10, 0.1);
  mesh.splitSlivers(4, 0);
  ASSERT_TRUE(mesh.hasUvs());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto c = mesh.corners(e);
    const auto uv = mesh.cornerUvs(e);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((uv[k] - c[k].head<2>() / 7).norm(), 0, 1e-12);
  }
}

TEST(SplitSlivers, NeverFlipsAcrossACrease) {
  // Two thin strips folded at a right angle along their shared long edge: flips would move the
  // surface off both planes, so every element must stay in its own plane.
  std::vector<Eigen::Vector3d> p = {{0, 0, 0},   {5, 0, 0},   {5, 0.1, 0},
                                    {0, 0.1, 0}, {5, 0, 0.1}, {0, 0, 0.1}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 1}});
  mesh.splitSlivers(4, 0);
  EXPECT_LE(worstAspect(mesh), 4.0);
  for (int e = 0; e < mesh.elementCount(); ++e)
    for (const auto& c : mesh.corners(e)) EXPECT_NEAR(mesh.patch(e) == 0 ? c.z() : c.y(), 0, 1e-12);
  expectConforming(mesh);
}

}  // namespace
}  // namespace rad
