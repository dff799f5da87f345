#include "radiosity/output/lightmap_bake.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "meshing/lightmap_charts.h"
#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"

namespace rad {
namespace {

using Vec2 = Eigen::Vector2d;

// Barycentric coordinates of p in triangle t (non-degenerate in texel space).
Eigen::Vector3d barycentric(const std::array<Vec2, 3>& t, const Vec2& p) {
  const Vec2 e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
  const double det = e1.x() * e2.y() - e1.y() * e2.x();
  const double b1 = (d.x() * e2.y() - d.y() * e2.x()) / det;
  const double b2 = (e1.x() * d.y() - e1.y() * d.x()) / det;
  return {1 - b1 - b2, b1, b2};
}

// Barycentrics of the point of t nearest to p (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d nearestBarycentric(const std::array<Vec2, 3>& t, const Vec2& p) {
  const Vec2 ab = t[1] - t[0], ac = t[2] - t[0], ap = p - t[0];
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Vec2 bp = p - t[1];
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Vec2 cp = p - t[2];
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

// Texel weights, a pure function of the element's triangle in texel space and the texel: the
// rasteriser's passes accept texels by them, and every texel's value is taken at them.
// Pass 1's: the texel's centre inside the element.
bool centreInside(const std::array<Vec2, 3>& t, int x, int y, Eigen::Vector3d& inside) {
  const Eigen::Vector3d b = barycentric(t, Vec2(x + 0.5, y + 0.5));
  if (b.minCoeff() < -1e-12 || !b.allFinite()) return false;
  inside = b.cwiseMax(0.0) / b.cwiseMax(0.0).sum();
  return true;
}

// Pass 2's: texels the element overlaps without holding their centre (chart borders, slivers)
// take the element's point nearest the centre.
bool nearestToCentre(const std::array<Vec2, 3>& t, int x, int y, Eigen::Vector3d& nearest) {
  const std::array<Vec2, 3> lower{Vec2(x, y), Vec2(x + 1, y), Vec2(x + 1, y + 1)};
  const std::array<Vec2, 3> upper{Vec2(x, y), Vec2(x + 1, y + 1), Vec2(x, y + 1)};
  if (!trianglesOverlap2d(t, lower, 1e-9) && !trianglesOverlap2d(t, upper, 1e-9)) return false;
  nearest = nearestBarycentric(t, Vec2(x + 0.5, y + 0.5));
  return true;
}

template <typename Row>
void forEachRow(int height, Row&& row) {
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y != r.end(); ++y) row(y);
  });
}

// Every texel an element owns takes evaluate(element, weights, texel), in parallel, at the
// weights its pass gave it (computed again: cheaper than keeping them for every texel).
void evaluateOwnedTexels(Lightmap& map, const LightmapLayout& layout,
                         const TexelEvaluator& evaluate, Progress* progress) {
  const int width = map.radiance.width;
  forEachRow(map.radiance.height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = map.index(x, y);
      const int e = map.element[i];
      if (e < 0) continue;
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      const auto& t = layout.texels[e];
      const bool accepted = map.state[i] == TexelState::Covered ? centreInside(t, x, y, b)
                                                                : nearestToCentre(t, x, y, b);
      RAD_CHECK(accepted);
      map.radiance.pixels[i] = evaluate(e, b, i);
    }
    if (progress) progress->advance(static_cast<uint64_t>(width));
  });
}

// The own (covered or partly covered) texels' charts next to (x, y): `first` and, where a second
// chart's own texels are there too, the lowest such `second`; -1 where none.
void ownCharts(const Lightmap& map, int x, int y, int& first, int& second) {
  const int width = map.radiance.width, height = map.radiance.height;
  first = second = -1;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      const size_t j = map.index(nx, ny);
      if (map.element[j] < 0) continue;
      const int c = map.chart[j];
      if (first < 0 || c == first)
        first = c;
      else if (second < 0 || c < second)
        second = c;
    }
}

// Texels next to (or on) the own texels of two charts: a bilinear lookup inside either chart
// may read them, so one of the two bleeds. Never with packed charts (their own texels are at
// least 2 × padding + 1 apart); scene UVs can place islands that close.
size_t crowdedTexels(const Lightmap& map) {
  const int width = map.radiance.width;
  return tbb::parallel_reduce(
      tbb::blocked_range<int>(0, map.radiance.height, 16), size_t{0},
      [&](const tbb::blocked_range<int>& r, size_t crowded) {
        for (int y = r.begin(); y != r.end(); ++y)
          for (int x = 0; x < width; ++x) {
            int first, second;
            ownCharts(map, x, y, first, second);
            crowded += second >= 0;
          }
        return crowded;
      },
      std::plus<size_t>());
}

// Dilation, map.dilationRadius rings, one at a time from a snapshot, so a ring reads only earlier
// rings. A texel next to a chart's own texels takes that chart (bilinear lookups inside it read
// the texel); one next to the own texels of two charts stays empty, as it cannot serve both.
void dilate(Lightmap& map) {
  const int width = map.radiance.width, height = map.radiance.height;
  for (int ring = 0; ring < map.dilationRadius; ++ring) {
    const std::vector<int> chartBefore = map.chart;
    // Rows in parallel: a texel filled in this ring reads only texels filled before it.
    forEachRow(height, [&](int y) {
      for (int x = 0; x < width; ++x) {
        const size_t i = map.index(x, y);
        if (chartBefore[i] >= 0) continue;
        int own, other;
        ownCharts(map, x, y, own, other);
        if (other >= 0) continue;
        int chosen = own;
        for (int dy = -1; dy <= 1 && own < 0; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const int c = chartBefore[map.index(nx, ny)];
            if (c >= 0 && (chosen < 0 || c < chosen)) chosen = c;
          }
        if (chosen < 0) continue;
        Rgb sum;
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            const size_t j = map.index(nx, ny);
            if (chartBefore[j] == chosen) sum += map.radiance.pixels[j], ++n;
          }
        map.radiance.pixels[i] = sum / n;
        map.chart[i] = chosen, map.state[i] = TexelState::Dilated;
      }
    });
  }
}

}  // namespace

size_t Lightmap::count(TexelState s) const {
  return static_cast<size_t>(std::count(state.begin(), state.end(), s));
}

Lightmap bakeLightmap(const PatchMesh& mesh, const LightmapLayout& layout,
                      const VertexInterpolation& interpolation,
                      const std::vector<Rgb>& vertexRadiance, int dilationRadius,
                      const TexelEvaluator& evaluate, int page) {
  RAD_CHECK_GE(dilationRadius, 0);
  RAD_CHECK_MSG(page >= 0 && page < layout.pages, "bakeLightmap: no such lightmap page");
  RAD_CHECK_LE(dilationRadius, layout.padding);  // more: charts would bleed into each other
  RAD_CHECK_EQ(vertexRadiance.size(), interpolation.vertexCount());  // one per output vertex
  const int width = layout.width, height = layout.height;
  Lightmap map;
  map.radiance = ImageRgb(width, height);
  map.chart.assign(static_cast<size_t>(width) * height, -1);
  map.element.assign(map.chart.size(), -1);
  map.state.assign(map.chart.size(), TexelState::Empty);
  map.dilationRadius = dilationRadius;

  auto value = [&](int e, const Eigen::Vector3d& b) {
    const auto& v = interpolation.triangle(e);
    return vertexRadiance[v[0]] * b[0] + vertexRadiance[v[1]] * b[1] + vertexRadiance[v[2]] * b[2];
  };

  const int elements = mesh.elementCount();
  const size_t texels = map.chart.size();
  Progress progress("lightmap", 2 * static_cast<uint64_t>(elements), "element passes");
  // Which element a texel goes to, per pass: the lowest-numbered one that accepts it, as when the
  // elements are rasterised one after another (first element wins on a shared edge), found in
  // parallel by an atomic minimum.
  std::unique_ptr<std::atomic<int>[]> owner(new std::atomic<int>[texels]);
  constexpr int kNoOwner = std::numeric_limits<int>::max();
  // One pass over the elements: each empty texel of an element's bounding box that
  // `weights(t, x, y, b)` accepts (t the element in texel space) takes the element, its chart,
  // `state` and the interpolated value at the barycentric weights b it gives. `weights` is a pure
  // function of its arguments: the texel's weights are computed again where they are needed.
  auto rasterise = [&](TexelState state, auto&& weights) {
    forEachRow(height, [&](int y) {
      for (int x = 0; x < width; ++x)
        owner[map.index(x, y)].store(kNoOwner, std::memory_order_relaxed);
    });
    tbb::parallel_for(
        tbb::blocked_range<int>(0, elements, 256), [&](const tbb::blocked_range<int>& r) {
          for (int e = r.begin(); e != r.end(); ++e) {
            if (layout.page(e) != page) continue;
            const auto& t = layout.texels[e];
            const Vec2 lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]),
                       hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
            const int x0 = std::max(0, static_cast<int>(std::floor(lo.x()))),
                      y0 = std::max(0, static_cast<int>(std::floor(lo.y())));
            const int x1 = std::min(width - 1, static_cast<int>(std::floor(hi.x()))),
                      y1 = std::min(height - 1, static_cast<int>(std::floor(hi.y())));
            for (int y = y0; y <= y1; ++y)
              for (int x = x0; x <= x1; ++x) {
                const size_t i = map.index(x, y);
                if (map.state[i] != TexelState::Empty) continue;
                Eigen::Vector3d b;
                if (!weights(t, x, y, b)) continue;
                int current = owner[i].load(std::memory_order_relaxed);
                while (e < current &&
                       !owner[i].compare_exchange_weak(current, e, std::memory_order_relaxed)) {
                }
              }
          }
          progress.advance(r.size());
        });
    forEachRow(height, [&](int y) {
      for (int x = 0; x < width; ++x) {
        const size_t i = map.index(x, y);
        const int e = owner[i].load(std::memory_order_relaxed);
        if (e == kNoOwner) continue;
        Eigen::Vector3d b = Eigen::Vector3d::Zero();
        const bool accepted = weights(layout.texels[e], x, y, b);  // as in the pass: same weights
        RAD_CHECK(accepted);
        map.radiance.pixels[i] = value(e, b);
        map.chart[i] = layout.chartOfElement[e], map.element[i] = e, map.state[i] = state;
      }
    });
  };
  // Pass 1: texel centres inside an element (first element wins on a shared edge).
  rasterise(TexelState::Covered, centreInside);
  // Pass 2: texels an element overlaps without holding their centre (chart borders, slivers).
  rasterise(TexelState::Conservative, nearestToCentre);
  owner.reset();
  progress.finish();
  if (evaluate) {
    Progress gathering("lightmap gather", texels, "texels");
    evaluateOwnedTexels(map, layout, evaluate, &gathering);
    gathering.finish();
  }

  map.crowdedTexels = crowdedTexels(map);
  dilate(map);
  return map;
}

Lightmap bakeOnTexels(const Lightmap& shape, const LightmapLayout& layout,
                      const TexelEvaluator& evaluate) {
  RAD_CHECK_MSG(static_cast<bool>(evaluate), "bakeOnTexels: no evaluator");
  RAD_CHECK_EQ(shape.radiance.width, layout.width);
  RAD_CHECK_EQ(shape.radiance.height, layout.height);
  Lightmap map;
  map.radiance = ImageRgb(layout.width, layout.height);
  map.element = shape.element;
  map.chart = shape.chart;
  map.state = shape.state;
  map.dilationRadius = shape.dilationRadius;
  map.crowdedTexels = shape.crowdedTexels;  // the own texels, on which it depends, are the same
  // The rings are dilated again from the new values: undo the shape's.
  for (size_t i = 0; i < map.state.size(); ++i)
    if (map.state[i] == TexelState::Dilated) map.chart[i] = -1, map.state[i] = TexelState::Empty;
  evaluateOwnedTexels(map, layout, evaluate, nullptr);
  dilate(map);
  return map;
}

}  // namespace rad
