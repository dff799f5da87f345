// Baking into the scene's own UVs (bake --use-scene-uvs): the Cornell box given one UV island
// per polygon in a grid, the layout that follows those UVs, UV islands as charts, and islands
// placed too close together.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "meshing/mesh_uv_layout.h"
#include "meshing/polygon_triangulation.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

using Vec2 = Eigen::Vector2d;

// A polygon's UVs: its plane's coordinates, scaled to fit one cell of a grid with a margin.
struct PolygonUvMap {
  Eigen::Vector3d origin, ex, ey;
  double scale = 1;
  Vec2 offset;
  Vec2 operator()(const Eigen::Vector3d& p) const {
    return offset + scale * Vec2((p - origin).dot(ex), (p - origin).dot(ey));
  }
};

struct UvScene {
  Scene scene;
  std::vector<PolygonUvMap> maps;  // per polygon
};

// The Cornell box with one island per polygon in an n × n grid of the unit square; islands keep
// `margin` (UV units) from their cell's edges.
UvScene cornellWithUvs(double margin) {
  UvScene s{loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj"), {}};
  const int count = static_cast<int>(s.scene.polygons.size());
  const int n = static_cast<int>(std::ceil(std::sqrt(count)));
  const double cell = 1.0 / n;
  for (int i = 0; i < count; ++i) {
    ScenePolygon& polygon = s.scene.polygons[i];
    std::vector<Eigen::Vector3d> points;
    for (int v : polygon.vertices) points.push_back(s.scene.positions[v]);
    PolygonUvMap map;
    const Eigen::Vector3d normal = newellNormal(points).normalized();
    map.origin = points[0];
    map.ex = normal.unitOrthogonal();
    map.ey = normal.cross(map.ex);
    Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
    for (const auto& p : points) {
      const Vec2 q((p - map.origin).dot(map.ex), (p - map.origin).dot(map.ey));
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
    map.scale = (cell - 2 * margin) / (hi - lo).maxCoeff();
    map.offset = Vec2((i % n) * cell + margin, (i / n) * cell + margin) - map.scale * lo;
    for (const auto& p : points) polygon.uvs.push_back(map(p));
    s.maps.push_back(map);
  }
  return s;
}

struct Baked {
  PatchMesh mesh;
  LightmapLayout layout;
  VertexInterpolation interpolation;
  std::vector<Rgb> vertexRadiance;
  Lightmap map;
};

// Radiosity varying smoothly over the scene, so an off-by-one texel or a swapped UV shows.
Baked bake(const Scene& scene, int side, int padding) {
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(0.002);
  std::vector<Rgb> radiosity(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Eigen::Vector3d c = mesh.centroid(e);
    radiosity[e] = Rgb(1 + c.x(), 1 + 2 * c.y(), 1 + 3 * c.z()) * M_PI;
  }
  LightmapLayout layout = layoutFromMeshUvs(mesh, side, side, padding);
  VertexInterpolation interpolation(mesh);
  std::vector<Rgb> vertexRadiance = interpolateVertexRadiance(interpolation, radiosity);
  Lightmap map = bakeLightmap(mesh, layout, interpolation, vertexRadiance, padding);
  return {std::move(mesh), std::move(layout), std::move(interpolation), std::move(vertexRadiance),
          std::move(map)};
}

TEST(SceneUvLightmap, LayoutFollowsTheScenesUvsThroughRefinement) {
  const UvScene s = cornellWithUvs(0.02);
  ASSERT_NO_THROW(checkLightmapUvs(s.scene));
  const Baked b = bake(s.scene, 256, 2);
  ASSERT_GT(b.mesh.elementCount(), 1000);
  // Each polygon is its own island here: one chart per polygon.
  ASSERT_EQ(b.layout.rects.size(), s.scene.polygons.size());
  std::vector<int> patchOfChart(b.layout.rects.size(), -1);
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    int& patch = patchOfChart[b.layout.chartOfElement[e]];
    if (patch < 0) patch = b.mesh.patch(e);
    ASSERT_EQ(patch, b.mesh.patch(e)) << "element " << e;
    const auto corners = b.mesh.corners(e);
    for (int k = 0; k < 3; ++k) {
      // Texel = (u W, (1 − v) H): the element corner's UV under its polygon's own map.
      const Vec2 uv = s.maps[b.mesh.patch(e)](corners[k]);
      ASSERT_NEAR(b.layout.texels[e][k].x(), uv.x() * 256, 1e-9) << "element " << e;
      ASSERT_NEAR(b.layout.texels[e][k].y(), (1 - uv.y()) * 256, 1e-9) << "element " << e;
    }
  }
  EXPECT_EQ(b.map.crowdedTexels, 0u);
}

TEST(SceneUvLightmap, TexelAtFaceCentreEqualsTheSolutionThere) {
  const Baked b = bake(cornellWithUvs(0.02).scene, 512, 2);
  int checked = 0;
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    const auto& t = b.layout.texels[e];
    const Vec2 c = (t[0] + t[1] + t[2]) / 3;
    const size_t i = b.map.index(int(c.x()), int(c.y()));
    if (b.map.element[i] != e) continue;  // a neighbour holds this texel centre
    const auto& v = b.interpolation.triangle(e);
    const Rgb atCentre =
        (b.vertexRadiance[v[0]] + b.vertexRadiance[v[1]] + b.vertexRadiance[v[2]]) / 3;
    // Linear over the element: the texel centre is within √2/2 texel of the centroid, so the
    // values differ by at most max|ΔL| · (√2/2) / (smallest altitude in texels).
    double minAltitude = INFINITY, spread = 0;
    const double area2 =
        std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
    for (int k = 0; k < 3; ++k) {
      minAltitude = std::min(minAltitude, area2 / (t[(k + 1) % 3] - t[k]).norm());
      for (int ch = 0; ch < 3; ++ch)
        spread = std::max(
            spread, std::abs(b.vertexRadiance[v[k]][ch] - b.vertexRadiance[v[(k + 1) % 3]][ch]));
    }
    const double tolerance = spread * (std::sqrt(0.5) / minAltitude) + 1e-9;
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_NEAR(b.map.radiance.pixels[i][ch], atCentre[ch], tolerance) << "element " << e;
    ++checked;
  }
  EXPECT_GT(checked, b.mesh.elementCount() * 8 / 10);
}

TEST(SceneUvLightmap, EveryFaceOwnsTexelsAndBilinearReadsOnlyItsChart) {
  // Coarse: elements of about a texel, and the small blocks' faces a few texels wide.
  const Baked b = bake(cornellWithUvs(0.02).scene, 128, 2);
  std::vector<int> owned(b.mesh.patchCount(), 0);  // texels per input face
  for (int id : b.map.element)
    if (id >= 0) ++owned[b.mesh.patch(id)];
  for (int p = 0; p < b.mesh.patchCount(); ++p) ASSERT_GE(owned[p], 1) << "face " << p;
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    const auto& t = b.layout.texels[e];
    const Vec2 c = (t[0] + t[1] + t[2]) / 3;
    std::vector<Vec2> samples{c};
    for (int k = 0; k < 3; ++k) samples.push_back(t[k] + (c - t[k]) * 1e-6);
    for (const Vec2& p : samples) {
      const int x0 = int(std::floor(p.x() - 0.5)), y0 = int(std::floor(p.y() - 0.5));
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = 0; dx <= 1; ++dx) {
          const size_t i = b.map.index(x0 + dx, y0 + dy);
          ASSERT_EQ(b.map.chart[i], b.layout.chartOfElement[e]) << "element " << e;
        }
    }
  }
}

// Two unit squares side by side sharing an edge in 3D, with UVs given per polygon.
PatchMesh twoSquares(const std::vector<Vec2>& left, const std::vector<Vec2>& right) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                                          {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0, left}, {{1, 4, 5, 2}, 0, right}});
  mesh.subdivideUniform(0.05);
  return mesh;
}

TEST(SceneUvLightmap, ChartsAreConnectedUvIslands) {
  const std::vector<Vec2> left{{0.1, 0.1}, {0.4, 0.1}, {0.4, 0.4}, {0.1, 0.4}};
  // The right square continues the left one's UVs across the shared edge: one island.
  const PatchMesh joined = twoSquares(left, {{0.4, 0.1}, {0.7, 0.1}, {0.7, 0.4}, {0.4, 0.4}});
  EXPECT_EQ(layoutFromMeshUvs(joined, 64, 64, 2).rects.size(), 1u);
  // The same geometry with the right square's UVs elsewhere: a seam, two islands.
  const PatchMesh cut = twoSquares(left, {{0.5, 0.5}, {0.8, 0.5}, {0.8, 0.8}, {0.5, 0.8}});
  const LightmapLayout layout = layoutFromMeshUvs(cut, 64, 64, 2);
  ASSERT_EQ(layout.rects.size(), 2u);
  // Each island's rectangle covers its UVs (v flipped): the left one [6.4, 25.6] x [38.4, 57.6].
  const ChartRect& r = layout.rects[layout.chartOfElement[0]];
  EXPECT_EQ(r.x, 6);
  EXPECT_EQ(r.x + r.width, 26);
  EXPECT_EQ(r.y, 38);
  EXPECT_EQ(r.y + r.height, 58);
}

TEST(SceneUvLightmap, IslandsTooCloseAreCountedAndNeverDilatedIntoEachOther) {
  // At 64 texels the islands' own texels touch: the left one ends at x = 25.6 (texel 25), the
  // right one starts at 26.88 (texel 26).
  const PatchMesh mesh = twoSquares({{0.1, 0.1}, {0.4, 0.1}, {0.4, 0.4}, {0.1, 0.4}},
                                    {{0.42, 0.1}, {0.72, 0.1}, {0.72, 0.4}, {0.42, 0.4}});
  const LightmapLayout layout = layoutFromMeshUvs(mesh, 64, 64, 2);
  VertexInterpolation interpolation(mesh);
  const Lightmap map = bakeLightmap(mesh, layout, interpolation,
                                    std::vector<Rgb>(interpolation.vertexCount(), Rgb::all(1)), 2);
  EXPECT_GT(map.crowdedTexels, 0u);
  // No dilated texel touches the own texels of a chart other than its own.
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const size_t i = map.index(x, y);
      if (map.state[i] != TexelState::Dilated) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= 64 || ny >= 64) continue;
          const size_t j = map.index(nx, ny);
          if (map.element[j] < 0) continue;
          ASSERT_EQ(map.chart[j], map.chart[i]) << x << "," << y;
        }
    }
}

}  // namespace
}  // namespace rad
