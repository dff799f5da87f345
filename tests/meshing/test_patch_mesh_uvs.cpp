// Texture coordinates through meshing: every element keeps its input polygon's UVs, and vertices
// made by bisection take the mean of their edge's ends, so an affine UV map survives any
// refinement exactly, on both sides of a UV seam.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <stdexcept>

#include "meshing/patch_mesh.h"
#include "radiosity/core/check.h"

namespace rad {
namespace {

// Two unit squares meeting at a right angle along x (an L), sharing the edge's two vertices but
// not its UVs: polygon 0 maps (x, y) and polygon 1 maps (x, z), each by its own affine map.
Eigen::Vector2d uvOf(int polygon, const Eigen::Vector3d& p) {
  if (polygon == 0) return {0.1 + 0.3 * p.x() + 0.05 * p.y(), 0.2 + 0.25 * p.y()};
  return {0.9 - 0.2 * p.x(), 0.6 + 0.3 * p.z() - 0.1 * p.x()};
}

PatchMesh makeUvL() {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                          {0, 1, 0}, {1, 0, 1}, {0, 0, 1}};
  std::vector<PatchPolygon> polygons = {{{0, 1, 2, 3}, 0, {}}, {{1, 0, 5, 4}, 1, {}}};
  for (int i = 0; i < 2; ++i)
    for (int v : polygons[i].vertices) polygons[i].uvs.push_back(uvOf(i, p[v]));
  return PatchMesh(p, polygons);
}

void expectAffineUvs(const PatchMesh& mesh) {
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto corners = mesh.corners(e);
    const auto uvs = mesh.cornerUvs(e);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d expected = uvOf(mesh.patch(e), corners[k]);
      ASSERT_NEAR(uvs[k].x(), expected.x(), 1e-12) << "element " << e << " corner " << k;
      ASSERT_NEAR(uvs[k].y(), expected.y(), 1e-12) << "element " << e << " corner " << k;
    }
  }
}

TEST(PatchMeshUvs, InputTrianglesKeepTheirPolygonsUvs) {
  const PatchMesh mesh = makeUvL();
  ASSERT_TRUE(mesh.hasUvs());
  expectAffineUvs(mesh);
}

TEST(PatchMeshUvs, BisectionInterpolatesAcrossASeam) {
  PatchMesh mesh = makeUvL();
  mesh.subdivideUniform(0.01);
  ASSERT_GT(mesh.elementCount(), 200);
  expectAffineUvs(mesh);
  // Local refinement at the seam: the split edge's new vertex gets a different UV on each side.
  for (int i = 0; i < 50; ++i) mesh.bisect(i % mesh.elementCount());
  expectAffineUvs(mesh);
}

TEST(PatchMeshUvs, MeshWithoutUvsSaysSoAndAWrongUvCountIsRefused) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const PatchMesh plain(p, {{{0, 1, 2}, 0, {}}, {{0, 2, 3}, 0, {}}});
  EXPECT_FALSE(plain.hasUvs());
  EXPECT_FALSE(plain.hasUvs(0));
  EXPECT_THROW(plain.cornerUvs(0), std::logic_error);
  EXPECT_THROW(PatchMesh(p, {{{0, 1, 2}, 0, {{0, 0}, {1, 0}}}}), rad::CheckFailure);
}

// Textured and untextured polygons in one scene: each element carries UVs exactly when its
// polygon had them, through any refinement; the mesh as a whole has UVs only when all do.
TEST(PatchMeshUvs, PolygonsWithAndWithoutUvsMix) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  PatchMesh mesh(p, {{{0, 1, 2}, 0, {{0, 0}, {1, 0}, {1, 1}}}, {{0, 2, 3}, 1, {}}});
  EXPECT_FALSE(mesh.hasUvs());
  mesh.subdivideUniform(0.01);
  ASSERT_GT(mesh.elementCount(), 50);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    ASSERT_EQ(mesh.hasUvs(e), mesh.patch(e) == 0) << "element " << e;
    if (!mesh.hasUvs(e)) continue;
    const auto corners = mesh.corners(e);
    const auto uvs = mesh.cornerUvs(e);
    for (int k = 0; k < 3; ++k)  // the map of polygon 0 is (u, v) = (x, y)
      EXPECT_NEAR((uvs[k] - corners[k].head<2>()).norm(), 0, 1e-12) << "element " << e;
  }
}

// A second, lightmap set (glTF's TEXCOORD_1) rides along with the texture set through bisection,
// sliver splitting and its flips: each stays its own affine map of position.
TEST(PatchMeshUvs, TheLightmapSetFollowsItsOwnAffineMapBesideTheTextureSet) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {8, 0, 0}, {8, 0.2, 0}, {0, 0.2, 0}};
  auto lightmapOf = [](const Eigen::Vector3d& q) {
    return Eigen::Vector2d(0.7 - 0.05 * q.x(), 0.1 + 2.0 * q.y());
  };
  std::vector<PatchPolygon> polygons = {{{0, 1, 2, 3}, 0, {}, {}}};
  for (int v : polygons[0].vertices) {
    polygons[0].uvs.push_back(uvOf(0, p[v]));
    polygons[0].lightmapUvs.push_back(lightmapOf(p[v]));
  }
  PatchMesh mesh(p, polygons);
  mesh.splitSlivers(4.0, 0.05);  // a 40:1 strip: bisections and Delaunay flips
  mesh.subdivideUniform(0.02);
  ASSERT_TRUE(mesh.hasUvs());
  ASSERT_TRUE(mesh.hasLightmapUvs());
  ASSERT_GT(mesh.elementCount(), 40);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto corners = mesh.corners(e);
    const auto uv = mesh.cornerUvs(e), lightmap = mesh.cornerLightmapUvs(e);
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR((uv[k] - uvOf(0, corners[k])).norm(), 0, 1e-12) << "element " << e;
      ASSERT_NEAR((lightmap[k] - lightmapOf(corners[k])).norm(), 0, 1e-12) << "element " << e;
    }
  }
}

// Without a lightmap set, the texture set is the lightmap set.
TEST(PatchMeshUvs, WithoutALightmapSetTheTextureUvsServe) {
  const PatchMesh mesh = makeUvL();
  ASSERT_TRUE(mesh.hasLightmapUvs());
  for (int e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.cornerLightmapUvs(e)[k], mesh.cornerUvs(e)[k]);
}

// A scene may mix polygons with and without UVs (a textured floor beside untextured slivers):
// splitting and flipping the ones without keeps every element's corner keys in step.
TEST(PatchMeshUvs, SliversWithoutUvsBesideTexturedPolygonsSplitAndFlip) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0},   {1, 1, 0},  {0, 1, 0},
                                          {8, 0, 0}, {8, 0.2, 0}, {1, 0.2, 0}};
  std::vector<PatchPolygon> polygons = {{{0, 1, 2, 3}, 0, {}}, {{1, 4, 5, 6}, 1, {}}};
  for (int v : polygons[0].vertices) polygons[0].uvs.push_back(uvOf(0, p[v]));
  PatchMesh mesh(p, polygons);
  mesh.splitSlivers(4.0, 0.05);
  mesh.subdivideUniform(0.01);
  ASSERT_FALSE(mesh.hasUvs());
  int textured = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    ASSERT_EQ(mesh.hasUvs(e), mesh.patch(e) == 0) << "element " << e;
    if (!mesh.hasUvs(e)) continue;
    ++textured;
    const auto corners = mesh.corners(e);
    const auto uv = mesh.cornerUvs(e);
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR((uv[k] - uvOf(0, corners[k])).norm(), 0, 1e-12) << "element " << e;
  }
  EXPECT_GT(textured, 50);
}

}  // namespace
}  // namespace rad
