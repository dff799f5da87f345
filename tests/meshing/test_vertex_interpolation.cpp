#include <gtest/gtest.h>

#include "meshing/vertex_interpolation.h"

namespace rad {
namespace {

TEST(VertexInterpolation, SplitsAtMaterialAndCreaseButNotInsideAPatch) {
  // Two unit squares at a right angle sharing an edge; then the same two coplanar.
  std::vector<Eigen::Vector3d> bent = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                       {0, 1, 0}, {1, 0, 1}, {0, 0, 1}};
  PatchMesh l(bent, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 0}});
  // 6 mesh vertices; the 2 on the crease are split in two.
  EXPECT_EQ(VertexInterpolation(l).vertexCount(), 8);

  std::vector<Eigen::Vector3d> flat = {{0, 0, 0}, {1, 0, 0},  {1, 1, 0},
                                       {0, 1, 0}, {1, -1, 0}, {0, -1, 0}};
  PatchMesh same(flat, {{{0, 1, 2, 3}, 0}, {{5, 4, 1, 0}, 0}});
  EXPECT_EQ(VertexInterpolation(same).vertexCount(), 6);
  PatchMesh different(flat, {{{0, 1, 2, 3}, 0}, {{5, 4, 1, 0}, 1}});
  EXPECT_EQ(VertexInterpolation(different).vertexCount(), 8);
}

TEST(VertexInterpolation, AreaWeightedMeanReproducesLinearFieldAtInteriorVertex) {
  std::vector<Eigen::Vector3d> flat = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  PatchMesh mesh(flat, {{{0, 1, 2, 3}, 0}});
  mesh.subdivideUniform(0.3);
  const VertexInterpolation interpolation(mesh);
  // A constant field stays constant at every vertex.
  std::vector<Eigen::Vector3d> values(mesh.elementCount(), Eigen::Vector3d(1, 2, 3));
  for (const auto& v : interpolation.interpolate(values))
    EXPECT_NEAR((v - Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_EQ(interpolation.vertexCount(), mesh.vertexCount());
}

TEST(VertexInterpolation, LinearFieldsThroughTheGaussPointsAreExactAtBordersAndCreases) {
  // Two squares at a right angle, each with its own linear field (the fold is a crease, so the
  // crease vertices take each side's own value). Sampled at each element's Gauss points, the
  // per-element planes evaluated at the corners and averaged reproduce both fields at every
  // vertex, border and crease included; the element means at the centroids do not (one-sided).
  std::vector<Eigen::Vector3d> bent = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                       {0, 1, 0}, {1, 0, 1}, {0, 0, 1}};
  PatchMesh mesh(bent, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 0}});
  mesh.subdivideUniform(0.02);
  const VertexInterpolation interpolation(mesh);
  auto field = [](const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
    const double onFloor = 1 + 3 * p.x() - 2 * p.y();  // the square at z = 0
    const double onWall = 2 + 5 * p.z() + p.x();       // the square at y = 0
    return Eigen::Vector3d(n.z() != 0 ? onFloor : onWall, 1, 0);
  };
  std::vector<std::array<Eigen::Vector3d, 3>> corners(mesh.elementCount());
  std::vector<Eigen::Vector3d> means(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto c = mesh.corners(e);
    std::array<Eigen::Vector3d, 3> gauss;
    for (int k = 0; k < 3; ++k)
      gauss[k] = field((4 * c[k] + c[(k + 1) % 3] + c[(k + 2) % 3]) / 6, mesh.normal(e));
    corners[e] = linearAtCorners(gauss);
    means[e] = field(mesh.centroid(e), mesh.normal(e));
  }
  const auto fromCorners = interpolation.interpolateCorners(corners);
  const auto fromMeans = interpolation.interpolate(means);
  double worstCorners = 0, worstMeans = 0;
  for (int v = 0; v < interpolation.vertexCount(); ++v) {
    const Eigen::Vector3d exact = field(interpolation.position(v), interpolation.normal(v));
    worstCorners = std::max(worstCorners, (fromCorners[v] - exact).norm());
    worstMeans = std::max(worstMeans, (fromMeans[v] - exact).norm());
  }
  EXPECT_LT(worstCorners, 1e-12);
  EXPECT_GT(worstMeans, 0.05);  // the one-sided means at the borders, about h·|∇L|
}

}  // namespace
}  // namespace rad
