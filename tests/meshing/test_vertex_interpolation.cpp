#include <gtest/gtest.h>

#include "meshing/vertex_interpolation.h"

namespace rad {
namespace {

TEST(VertexInterpolation, SplitsAtMaterialAndCreaseButNotInsideAPatch) {
  // Two unit squares at a right angle sharing an edge; then the same two coplanar.
  std::vector<Eigen::Vector3d> bent = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 1}, {0, 0, 1}};
  PatchMesh l(bent, {{{0, 1, 2, 3}, 0}, {{1, 0, 5, 4}, 0}});
  // 6 mesh vertices; the 2 on the crease are split in two.
  EXPECT_EQ(VertexInterpolation(l).vertexCount(), 8);

  std::vector<Eigen::Vector3d> flat = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, -1, 0}, {0, -1, 0}};
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
  for (const auto& v : interpolation.interpolate(values)) EXPECT_NEAR((v - Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_EQ(interpolation.vertexCount(), mesh.vertexCount());
}

}  // namespace
}  // namespace rad
