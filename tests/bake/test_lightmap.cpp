// Lightmap charts, packing and baking on the Cornell box mesh and on a spiral ramp whose planar
// projection would overlap itself.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <map>
#include <set>

#include "meshing/lightmap_charts.h"
#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/output/lightmap_baked_mesh.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

using Vec2 = Eigen::Vector2d;

PatchMesh cornellMesh() {
  PatchMesh mesh = buildPatchMesh(
      loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj"));
  mesh.subdivideUniform(0.002);
  return mesh;
}

// A ramp winding 1.5 turns around the z axis, rising slowly: every quad faces about +z, but a
// projection along z overlaps itself after one turn, so the charts must split.
PatchMesh spiralRamp() {
  std::vector<Eigen::Vector3d> positions;
  std::vector<PatchPolygon> polygons;
  const int steps = 36;
  for (int i = 0; i <= steps; ++i) {
    const double a = 3 * M_PI * i / steps, z = 0.3 * i / steps;
    positions.emplace_back(std::cos(a), std::sin(a), z);
    positions.emplace_back(2 * std::cos(a), 2 * std::sin(a), z);
  }
  for (int i = 0; i < steps; ++i) polygons.push_back({{2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2}, 0});
  PatchMesh mesh(positions, polygons);
  mesh.subdivideUniform(0.02);
  return mesh;
}

// Which charts claim each of 4×4 sub-samples per texel of `page`: independent of the baker's
// rasteriser.
int overlappingSamples(const LightmapLayout& layout, int page = 0) {
  const int s = 4;
  std::vector<int> owner(static_cast<size_t>(layout.width * s) * layout.height * s, -1);
  int overlaps = 0;
  for (size_t e = 0; e < layout.texels.size(); ++e) {
    if (layout.page(static_cast<int>(e)) != page) continue;
    const auto& t = layout.texels[e];
    const Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]) * s,
               hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]) * s;
    for (int y = std::max(0, int(lo.y())); y <= std::min(layout.height * s - 1, int(hi.y())); ++y)
      for (int x = std::max(0, int(lo.x())); x <= std::min(layout.width * s - 1, int(hi.x()));
           ++x) {
        const Vec2 p((x + 0.5) / s, (y + 0.5) / s);
        bool inside = true;
        for (int k = 0; k < 3; ++k) {
          const Vec2 a = t[k], b = t[(k + 1) % 3];
          const double c = (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
          const double c2 =
              (t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x();
          if (c * c2 < 0) inside = false;
        }
        if (!inside) continue;
        int& o = owner[static_cast<size_t>(y) * layout.width * s + x];
        if (o >= 0 && o != layout.chartOfElement[e]) ++overlaps;
        o = layout.chartOfElement[e];
      }
  }
  return overlaps;
}

// Every rect inside its page, and no two rects of one page overlap.
bool rectsDisjoint(const LightmapLayout& l) {
  for (size_t a = 0; a < l.rects.size(); ++a) {
    const ChartRect& r = l.rects[a];
    if (r.x < 0 || r.y < 0 || r.x + r.width > l.width || r.y + r.height > l.height) return false;
    if (r.page < 0 || r.page >= l.pages) return false;
    for (size_t b = a + 1; b < l.rects.size(); ++b) {
      const ChartRect& q = l.rects[b];
      if (q.page == r.page && r.x < q.x + q.width && q.x < r.x + r.width && r.y < q.y + q.height &&
          q.y < r.y + r.height)
        return false;
    }
  }
  return true;
}

struct Baked {
  PatchMesh mesh;
  LightmapCharts charts;
  LightmapLayout layout;
  VertexInterpolation interpolation;
  std::vector<Rgb> vertexRadiance;
  Lightmap map;
};

// Radiosity varying smoothly over the scene (B = 1 + x + 2y + 3z per channel, scaled), so texel
// values differ from face to face and an off-by-one texel or swapped UV shows.
Baked bake(PatchMesh mesh, const LightmapPackOptions& pack) {
  std::vector<Rgb> radiosity(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Eigen::Vector3d c = mesh.centroid(e);
    radiosity[e] = Rgb(1 + c.x(), 1 + 2 * c.y(), 1 + 3 * c.z()) * M_PI;
  }
  LightmapCharts charts = buildLightmapCharts(mesh);
  LightmapLayout layout = packLightmapCharts(charts, pack);
  VertexInterpolation interpolation(mesh);
  std::vector<Rgb> vertexRadiance = interpolateVertexRadiance(interpolation, radiosity);
  Lightmap map = bakeLightmap(mesh, layout, interpolation, vertexRadiance, pack.padding);
  return {std::move(mesh),          std::move(charts),         std::move(layout),
          std::move(interpolation), std::move(vertexRadiance), std::move(map)};
}

TEST(LightmapCharts, CornellChartsNeverOverlapAndRectsAreDisjoint) {
  const Baked b = bake(cornellMesh(), {0, 256, 2});
  EXPECT_EQ(overlappingSamples(b.layout), 0);
  EXPECT_TRUE(rectsDisjoint(b.layout));
  // Walls at right angles never share a chart (30° threshold); the 17 patches give 16 charts
  // because the non-planar left wall's two triangles are coplanar within 1°.
  EXPECT_GE(b.charts.charts.size(), 16u);
}

TEST(LightmapCharts, SpiralRampSplitsInsteadOfOverlapping) {
  const Baked b = bake(spiralRamp(), {0, 256, 2});
  EXPECT_GE(b.charts.charts.size(), 2u);
  EXPECT_EQ(overlappingSamples(b.layout), 0);
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    int texels = 0;
    for (int id : b.map.element) texels += id == e;
    ASSERT_GE(texels, 1) << "element " << e;
  }
}

TEST(LightmapBake, EveryFaceOwnsATexel) {
  const Baked b = bake(cornellMesh(), {0, 128, 2});  // coarse: many elements smaller than a texel
  std::vector<int> owned(b.mesh.elementCount(), 0);
  for (int id : b.map.element)
    if (id >= 0) ++owned[id];
  for (int e = 0; e < b.mesh.elementCount(); ++e) ASSERT_GE(owned[e], 1) << "element " << e;
}

// The elements are rasterised in parallel, each texel going to the lowest-numbered element that
// claims it: the page must not depend on how many threads baked it or in which order they ran.
// The exported mesh splits a vertex only where its chart (or its texture UV) changes: the Cornell
// box has no texture UVs, so its glTF/OBJ vertices are exactly the (vertex, chart) pairs of its
// element corners. (Its elements' missing texture UVs were once left unset in the vertex keys,
// which split vertices as whatever the stack held.)
TEST(LightmapBakedMesh, WithoutTextureUvsAVertexSplitsOnlyBetweenCharts) {
  const PatchMesh mesh = cornellMesh();
  const LightmapLayout layout = packLightmapCharts(buildLightmapCharts(mesh), {0, 256, 2, 256});
  const VertexInterpolation interpolation(mesh);
  const std::vector<Rgb> radiance(interpolation.vertexCount());
  const BakedMesh baked =
      makeBakedMesh(mesh, interpolation, radiance, &layout, {"white", "red", "green", "light"});
  std::set<std::pair<int, int>> vertexCharts;
  for (int e = 0; e < mesh.elementCount(); ++e)
    for (int v : interpolation.triangle(e)) vertexCharts.insert({v, layout.chartOfElement[e]});
  EXPECT_TRUE(baked.textureUvs.empty());
  EXPECT_EQ(baked.positions.size(), vertexCharts.size());
}

// A two-sided surface is two coincident copies facing apart. Exported as they are, a renderer that
// does not cull back faces (Cycles) shows whichever copy a ray meets first: the wrong side's light
// over about half the surface (the shared staircase baked --two-sided, in Blender). The back copy
// goes out moved behind the front one along its own normal, so each side's ray meets its own copy.
TEST(LightmapBakedMesh, TwoSidedBackCopiesLieBehindTheirFrontSides) {
  const std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  const PatchMesh mesh(square, {PatchPolygon({0, 1, 2, 3}, 0), PatchPolygon({0, 3, 2, 1}, 0)});
  const VertexInterpolation interpolation(mesh);
  const std::vector<Rgb> radiance(interpolation.vertexCount());
  const BakedMesh baked = makeBakedMesh(mesh, interpolation, radiance, nullptr, {"grey"}, {0, 1});
  const double lift = kBackSideLift * mesh.boundsDiagonal();
  int front = 0, back = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const bool isBack = mesh.patch(e) == 1;
    ASSERT_EQ(mesh.normal(e).z(), isBack ? -1.0 : 1.0);
    for (int v : baked.triangles[e]) {
      // Front: exactly in place; back: lifted along its normal (-z), away from the front side.
      EXPECT_DOUBLE_EQ(baked.positions[v].z(), isBack ? -lift : 0.0) << "element " << e;
      (isBack ? back : front) += 1;
    }
  }
  EXPECT_GT(front, 0);
  EXPECT_GT(back, 0);
  // One-sided surfaces stay where they are.
  const BakedMesh plain = makeBakedMesh(mesh, interpolation, radiance, nullptr, {"grey"});
  for (const Eigen::Vector3d& p : plain.positions) EXPECT_EQ(p.z(), 0.0);
}

TEST(LightmapBake, OneThreadAndManyBakeTheSamePage) {
  const Baked many = bake(cornellMesh(), {0, 128, 2});  // coarse: texels shared by many elements
  // With an evaluator (as the bake's texture detail and per-texel gather use) returning the
  // interpolated value at the weights it is given: it must be given the rasteriser's own weights.
  const auto interpolated = [&](int e, const Eigen::Vector3d& b, size_t) {
    const auto& v = many.interpolation.triangle(e);
    return many.vertexRadiance[v[0]] * b[0] + many.vertexRadiance[v[1]] * b[1] +
           many.vertexRadiance[v[2]] * b[2];
  };
  Lightmap one, oneEvaluated;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = bakeLightmap(many.mesh, many.layout, many.interpolation, many.vertexRadiance, 2);
    oneEvaluated = bakeLightmap(many.mesh, many.layout, many.interpolation, many.vertexRadiance, 2,
                                interpolated);
  }
  const Lightmap manyEvaluated = bakeLightmap(many.mesh, many.layout, many.interpolation,
                                              many.vertexRadiance, 2, interpolated);
  EXPECT_EQ(one.element, many.map.element);
  EXPECT_EQ(one.chart, many.map.chart);
  EXPECT_TRUE(one.state == many.map.state);
  EXPECT_EQ(one.crowdedTexels, many.map.crowdedTexels);
  ASSERT_EQ(one.radiance.pixels.size(), many.map.radiance.pixels.size());
  size_t differing = 0;
  for (size_t i = 0; i < one.radiance.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      differing += (oneEvaluated.radiance.pixels[i][c] != many.map.radiance.pixels[i][c]) +
                   (manyEvaluated.radiance.pixels[i][c] != many.map.radiance.pixels[i][c]);
  for (size_t i = 0; i < one.radiance.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      differing += one.radiance.pixels[i][c] != many.map.radiance.pixels[i][c];
  EXPECT_EQ(differing, 0u);
  // The rule itself, by brute force: a covered texel belongs to the lowest-numbered element
  // holding its centre, any other touched texel to the lowest-numbered element overlapping it;
  // and some texels are overlapped by several elements, so the order of the elements mattered.
  const LightmapLayout& layout = many.layout;
  const size_t texels = many.map.element.size();
  std::vector<int> lowestHolder(texels, -1), lowestOverlap(texels, -1), overlaps(texels, 0);
  for (int e = 0; e < many.mesh.elementCount(); ++e) {
    const auto& t = layout.texels[e];
    const Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]), hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    for (int y = std::max(0, int(lo.y())); y <= std::min(layout.height - 1, int(hi.y())); ++y)
      for (int x = std::max(0, int(lo.x())); x <= std::min(layout.width - 1, int(hi.x())); ++x) {
        const size_t i = many.map.index(x, y);
        const Vec2 p(x + 0.5, y + 0.5);
        const Vec2 e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
        const double det = e1.x() * e2.y() - e1.y() * e2.x();
        const double b1 = (d.x() * e2.y() - d.y() * e2.x()) / det,
                     b2 = (e1.x() * d.y() - e1.y() * d.x()) / det;
        if (std::min({1 - b1 - b2, b1, b2}) >= -1e-12 && lowestHolder[i] < 0) lowestHolder[i] = e;
        const std::array<Vec2, 3> lower{Vec2(x, y), Vec2(x + 1, y), Vec2(x + 1, y + 1)};
        const std::array<Vec2, 3> upper{Vec2(x, y), Vec2(x + 1, y + 1), Vec2(x, y + 1)};
        if (trianglesOverlap2d(t, lower, 1e-9) || trianglesOverlap2d(t, upper, 1e-9)) {
          if (lowestOverlap[i] < 0) lowestOverlap[i] = e;
          ++overlaps[i];
        }
      }
  }
  size_t shared = 0, wrongOwner = 0;
  for (size_t i = 0; i < texels; ++i) {
    const TexelState state = many.map.state[i];
    if (state == TexelState::Covered) wrongOwner += many.map.element[i] != lowestHolder[i];
    if (state == TexelState::Empty || state == TexelState::Dilated)
      wrongOwner += lowestOverlap[i] >= 0 || many.map.element[i] >= 0;
    if (state == TexelState::Conservative) {
      wrongOwner += lowestHolder[i] >= 0 || many.map.element[i] != lowestOverlap[i];
      shared += overlaps[i] > 1;
    }
  }
  EXPECT_EQ(wrongOwner, 0u);
  EXPECT_GT(shared, 0u);
}

// Another quantity on a baked page's texels (the confidence map, a light group's layer) equals a
// bake of its own with that evaluator, texel for texel: the same owners, the same weights, the
// dilated rings filled again from the new values.
TEST(LightmapBake, AQuantityOnAPagesTexelsEqualsABakeOfItsOwn) {
  const Baked b = bake(cornellMesh(), {0, 128, 2});  // coarse: partly covered and dilated texels
  ASSERT_GT(b.map.count(TexelState::Conservative), 0u);
  ASSERT_GT(b.map.count(TexelState::Dilated), 0u);
  // Different from the page's own values everywhere, varying with the element and the weights.
  const auto other = [](int e, const Eigen::Vector3d& w, size_t texel) {
    return Rgb(1 + e, w[1] + 2 * w[2], static_cast<double>(texel % 7));
  };
  const Lightmap own = bakeLightmap(b.mesh, b.layout, b.interpolation, b.vertexRadiance, 2, other);
  const Lightmap onTexels = bakeOnTexels(b.map, b.layout, other);
  EXPECT_EQ(onTexels.element, own.element);
  EXPECT_EQ(onTexels.chart, own.chart);
  EXPECT_TRUE(onTexels.state == own.state);
  EXPECT_EQ(onTexels.crowdedTexels, own.crowdedTexels);
  EXPECT_EQ(onTexels.dilationRadius, own.dilationRadius);
  size_t differing = 0;
  for (size_t i = 0; i < own.radiance.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      differing += onTexels.radiance.pixels[i][c] != own.radiance.pixels[i][c];
  EXPECT_EQ(differing, 0u);
}

TEST(LightmapBake, PaddingAtLeastDilationAndGeometryInsideItsRect) {
  const Baked b = bake(cornellMesh(), {0.01, 0, 3});
  EXPECT_GE(b.layout.padding, b.map.dilationRadius);
  for (size_t e = 0; e < b.layout.texels.size(); ++e) {
    const ChartRect& r = b.layout.rects[b.layout.chartOfElement[e]];
    for (const Vec2& p : b.layout.texels[e]) {
      EXPECT_GE(p.x(), r.x + b.layout.padding - 1e-9);
      EXPECT_LE(p.x(), r.x + r.width - b.layout.padding + 1e-9);
      EXPECT_GE(p.y(), r.y + b.layout.padding - 1e-9);
      EXPECT_LE(p.y(), r.y + r.height - b.layout.padding + 1e-9);
    }
  }
  EXPECT_THROW(bakeLightmap(b.mesh, b.layout, b.interpolation, b.vertexRadiance, 4), CheckFailure);
  // With --texel-size the density is what was asked for.
  EXPECT_DOUBLE_EQ(b.layout.texelSize, 0.01);
}

TEST(LightmapBake, TexelAtFaceCentreEqualsTheSolutionThere) {
  const Baked b = bake(cornellMesh(), {0, 512, 2});
  int checked = 0;
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    const auto& t = b.layout.texels[e];
    const Vec2 c = (t[0] + t[1] + t[2]) / 3;
    const int x = int(c.x()), y = int(c.y());
    const size_t i = b.map.index(x, y);
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
      for (int c2 = 0; c2 < 3; ++c2)
        spread = std::max(
            spread, std::abs(b.vertexRadiance[v[k]][c2] - b.vertexRadiance[v[(k + 1) % 3]][c2]));
    }
    const double tolerance = spread * (std::sqrt(0.5) / minAltitude) + 1e-9;
    for (int ch = 0; ch < 3; ++ch)
      ASSERT_NEAR(b.map.radiance.pixels[i][ch], atCentre[ch], tolerance) << "element " << e;
    ++checked;
  }
  EXPECT_GT(checked, b.mesh.elementCount() * 9 / 10);
}

TEST(LightmapBake, BilinearSamplesInsideAFaceReadOnlyItsChart) {
  const Baked b = bake(cornellMesh(), {0, 256, 2});
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    const auto& t = b.layout.texels[e];
    const Vec2 c = (t[0] + t[1] + t[2]) / 3;
    std::vector<Vec2> samples{c};
    for (int k = 0; k < 3; ++k) {
      samples.push_back(t[k] + (c - t[k]) * 1e-6);
      samples.push_back((t[k] + t[(k + 1) % 3]) / 2 + (c - (t[k] + t[(k + 1) % 3]) / 2) * 1e-6);
    }
    for (const Vec2& p : samples) {
      const int x0 = int(std::floor(p.x() - 0.5)), y0 = int(std::floor(p.y() - 0.5));
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = 0; dx <= 1; ++dx) {
          const size_t i = b.map.index(x0 + dx, y0 + dy);
          ASSERT_EQ(b.map.chart[i], b.layout.chartOfElement[e]) << "element " << e;
          ASSERT_NE(b.map.state[i], TexelState::Empty);
        }
    }
  }
}

TEST(LightmapBake, UnlitChartsGetValidBlackTexels) {
  PatchMesh mesh = cornellMesh();
  LightmapCharts charts = buildLightmapCharts(mesh);
  LightmapLayout layout = packLightmapCharts(charts, {0, 128, 2});
  std::vector<Rgb> radiosity(mesh.elementCount(), Rgb::all(1.0));
  const int dark = charts.chartOfElement[0];
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (charts.chartOfElement[e] == dark) radiosity[e] = Rgb();
  VertexInterpolation interpolation(mesh);
  const Lightmap map = bakeLightmap(mesh, layout, interpolation,
                                    interpolateVertexRadiance(interpolation, radiosity), 2);
  int texels = 0;
  for (size_t i = 0; i < map.chart.size(); ++i)
    if (map.chart[i] == dark) {
      ++texels;
      EXPECT_TRUE(map.radiance.pixels[i].isZero());
    }
  EXPECT_GT(texels, 0);
}

// Charts too many for one small page go on several: each chart on one page, inside its rect, no
// overlap on any page, every element baked on its own page only, and every texel of every page
// either empty or owned by a chart of that page.
TEST(LightmapPages, ChartsSpreadOverSeveralPagesWithoutOverlap) {
  PatchMesh mesh = cornellMesh();
  const LightmapCharts charts = buildLightmapCharts(mesh);
  // 0.01 units per texel: each wall of the 0.55-unit box is ~56 texels (+4 of padding), so a
  // 64² page holds one wall and the box needs many pages.
  const LightmapLayout layout = packLightmapCharts(charts, {0.01, 0, 2, 64});
  ASSERT_GT(layout.pages, 1);
  EXPECT_LE(layout.width, 64);
  EXPECT_LE(layout.height, 64);
  EXPECT_TRUE(rectsDisjoint(layout));
  EXPECT_DOUBLE_EQ(layout.texelSize, 0.01);
  std::vector<int> chartsOnPage(layout.pages, 0);
  for (const ChartRect& r : layout.rects) ++chartsOnPage[r.page];
  for (int p = 0; p < layout.pages; ++p) {
    EXPECT_GT(chartsOnPage[p], 0) << "page " << p << " is empty";
    EXPECT_EQ(overlappingSamples(layout, p), 0) << "page " << p;
  }

  std::vector<Rgb> radiosity(mesh.elementCount(), Rgb::all(M_PI));
  const VertexInterpolation interpolation(mesh);
  const std::vector<Rgb> vertexRadiance = interpolateVertexRadiance(interpolation, radiosity);
  std::vector<int> ownedTexels(mesh.elementCount(), 0);
  for (int p = 0; p < layout.pages; ++p) {
    const Lightmap map = bakeLightmap(mesh, layout, interpolation, vertexRadiance, 2, {}, p);
    ASSERT_EQ(map.radiance.width, layout.width);
    for (int y = 0; y < layout.height; ++y)
      for (int x = 0; x < layout.width; ++x) {
        const size_t i = map.index(x, y);
        if (map.state[i] == TexelState::Empty) continue;
        const int c = map.chart[i];
        ASSERT_GE(c, 0);
        const ChartRect& r = layout.rects[c];
        ASSERT_EQ(r.page, p) << "a texel of page " << p << " holds a chart of page " << r.page;
        ASSERT_TRUE(x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height);
        if (map.element[i] >= 0) {
          ASSERT_EQ(layout.page(map.element[i]), p);
          ++ownedTexels[map.element[i]];
        }
        ASSERT_NEAR(map.radiance.pixels[i].g, 1.0, 1e-12);  // B = π everywhere: L = 1
      }
  }
  for (int e = 0; e < mesh.elementCount(); ++e) ASSERT_GE(ownedTexels[e], 1) << "element " << e;
  EXPECT_THROW(bakeLightmap(mesh, layout, interpolation, vertexRadiance, 2, {}, layout.pages),
               CheckFailure);
}

TEST(LightmapPages, OneChartLargerThanAPageIsAnInputError) {
  const LightmapCharts charts = buildLightmapCharts(cornellMesh());
  // 0.005 units per texel: a wall is ~112 texels, more than a 64² page.
  try {
    packLightmapCharts(charts, {0.005, 0, 2, 64});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--texel-density"), std::string::npos) << e.what();
  }
}

TEST(LightmapPages, OnePageWhenTheChartsFit) {
  const LightmapLayout layout =
      packLightmapCharts(buildLightmapCharts(cornellMesh()), {0.01, 0, 2, 4096});
  EXPECT_EQ(layout.pages, 1);
  EXPECT_TRUE(rectsDisjoint(layout));
}

PatchMesh scaledCornellMesh(double scale) {
  Scene scene = loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj");
  for (Eigen::Vector3d& p : scene.positions) p *= scale;
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(0.002 * scale * scale);
  return mesh;
}

// The default texel size follows the scene: kDefaultLightmapTexels texels of geometry whatever
// the unit, so a scene scaled ×1000 gets texels ×1000 larger and the same atlas.
TEST(LightmapPages, DefaultTexelSizeScalesWithTheScene) {
  const PatchMesh metres = scaledCornellMesh(1.0), millimetres = scaledCornellMesh(1000.0);
  const double t = defaultTexelSize(metres), t1000 = defaultTexelSize(millimetres);
  EXPECT_NEAR(t1000 / t, 1000.0, 1e-9 * 1000);
  double area = 0;
  for (int e = 0; e < metres.elementCount(); ++e) area += metres.area(e);
  EXPECT_NEAR(area / (t * t), kDefaultLightmapTexels, 1e-6 * kDefaultLightmapTexels);
  const LightmapLayout a = packLightmapCharts(buildLightmapCharts(metres), {t, 0, 2, 4096});
  const LightmapLayout b =
      packLightmapCharts(buildLightmapCharts(millimetres), {t1000, 0, 2, 4096});
  EXPECT_EQ(a.pages, b.pages);
  EXPECT_EQ(a.rects.size(), b.rects.size());
  // Rect sides are ceilings of chart size over texel size: equal up to rounding at a boundary.
  EXPECT_NEAR(a.width, b.width, 0.01 * a.width);
  EXPECT_NEAR(a.height, b.height, 0.01 * a.height);
}

}  // namespace
}  // namespace rad
