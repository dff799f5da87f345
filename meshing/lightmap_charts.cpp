#include "meshing/lightmap_charts.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace rad {
namespace {

using Tri2 = std::array<Eigen::Vector2d, 3>;

struct Frame {
  Eigen::Vector3d u, v;
  Eigen::Vector2d project(const Eigen::Vector3d& p) const { return {p.dot(u), p.dot(v)}; }
};

// Tangent frame with u × v = n, so a triangle facing n keeps its counter-clockwise winding.
Frame frameFor(const Eigen::Vector3d& n) {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  if (std::abs(n.y()) < std::abs(n.x()) && std::abs(n.y()) <= std::abs(n.z()))
    axis = Eigen::Vector3d::UnitY();
  else if (std::abs(n.z()) < std::abs(n.x()))
    axis = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d u = n.cross(axis).normalized();
  return {u, n.cross(u)};
}

double signedArea(const Tri2& t) {
  return 0.5 * ((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
}

// Uniform grid over projected triangles for overlap queries (charts can hold thousands).
class TriangleGrid {
 public:
  explicit TriangleGrid(double cell) : cell_(cell) {}
  template <class F>
  bool anyNear(const Tri2& t, F&& f) const {
    bool hit = false;
    forCells(t, [&](int64_t key) {
      auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (int id : it->second)
        if (!hit && f(id)) hit = true;
    });
    return hit;
  }
  void insert(const Tri2& t, int id) {
    forCells(t, [&](int64_t key) { cells_[key].push_back(id); });
  }

 private:
  template <class F>
  void forCells(const Tri2& t, F&& f) const {
    Eigen::Vector2d lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]),
                    hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    const int64_t x0 = static_cast<int64_t>(std::floor(lo.x() / cell_)),
                  x1 = static_cast<int64_t>(std::floor(hi.x() / cell_));
    const int64_t y0 = static_cast<int64_t>(std::floor(lo.y() / cell_)),
                  y1 = static_cast<int64_t>(std::floor(hi.y() / cell_));
    for (int64_t y = y0; y <= y1; ++y)
      for (int64_t x = x0; x <= x1; ++x)
        f(static_cast<int64_t>((static_cast<uint64_t>(x) << 32) ^
                               (static_cast<uint64_t>(y) & 0xffffffffu)));  // no signed shift (UB)
  }
  double cell_;
  std::unordered_map<int64_t, std::vector<int>> cells_;
};

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

// Rotates the chart to its smallest bounding rectangle (one side lies on a hull edge) and moves
// the box's corner to the origin: rectangles pack with less waste.
Eigen::Vector2d orientChart(std::vector<Tri2*>& tris) {
  std::vector<Eigen::Vector2d> points;
  for (Tri2* t : tris) points.insert(points.end(), t->begin(), t->end());
  const std::vector<Eigen::Vector2d> hull = convexHull(points);
  Eigen::Vector2d bestDir(1, 0);
  double bestArea = INFINITY;
  for (size_t i = 0; i < hull.size(); ++i) {
    Eigen::Vector2d d = hull[(i + 1) % hull.size()] - hull[i];
    if (d.norm() == 0) continue;
    d.normalize();
    double minA = INFINITY, maxA = -INFINITY, minB = INFINITY, maxB = -INFINITY;
    for (const auto& q : hull) {
      const double a = q.dot(d), b = q.x() * -d.y() + q.y() * d.x();
      minA = std::min(minA, a), maxA = std::max(maxA, a), minB = std::min(minB, b),
      maxB = std::max(maxB, b);
    }
    const double area = (maxA - minA) * (maxB - minB);
    if (area < bestArea * (1 - 1e-9)) bestArea = area, bestDir = d;
  }
  // Rotation by -angle(bestDir) keeps orientation (no mirroring).
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (Tri2* t : tris)
    for (auto& q : *t) {
      q = Eigen::Vector2d(q.dot(bestDir), q.x() * -bestDir.y() + q.y() * bestDir.x());
      lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    }
  for (Tri2* t : tris)
    for (auto& q : *t) q -= lo;
  return hi - lo;
}

}  // namespace

bool trianglesOverlap2d(const Tri2& a, const Tri2& b, double eps) {
  // Separating axis test over the six edge normals: separated (or merely touching) on any axis
  // means the interiors do not overlap.
  for (const Tri2* t : {&a, &b})
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector2d e = (*t)[(i + 1) % 3] - (*t)[i];
      const Eigen::Vector2d n(-e.y(), e.x());
      const double len = n.norm();
      if (len == 0) continue;
      double minA = INFINITY, maxA = -INFINITY, minB = INFINITY, maxB = -INFINITY;
      for (int k = 0; k < 3; ++k) {
        const double pa = a[k].dot(n) / len, pb = b[k].dot(n) / len;
        minA = std::min(minA, pa), maxA = std::max(maxA, pa), minB = std::min(minB, pb),
        maxB = std::max(maxB, pb);
      }
      if (maxA <= minB + eps || maxB <= minA + eps) return false;
    }
  return true;
}

LightmapCharts buildLightmapCharts(const PatchMesh& mesh, const LightmapChartOptions& options) {
  const int elementCount = mesh.elementCount(), patchCount = mesh.patchCount();
  const double cosMax = std::cos(options.maxAngleDegrees * M_PI / 180.0);
  std::vector<std::vector<int>> patchElements(patchCount);
  std::vector<Eigen::Vector3d> patchNormal(patchCount, Eigen::Vector3d::Zero());
  std::vector<double> patchArea(patchCount, 0.0);
  for (int e = 0; e < elementCount; ++e) {
    const int p = mesh.patch(e);
    patchElements[p].push_back(e);
    patchNormal[p] += mesh.area(e) * mesh.normal(e);
    patchArea[p] += mesh.area(e);
  }
  for (auto& n : patchNormal)
    n = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();

  // Patches are adjacent when an edge of the conforming mesh has one on each side.
  std::vector<std::vector<int>> neighbours(patchCount);
  const TriMesh& tm = mesh.mesh();
  for (auto eh : tm.edges()) {
    if (tm.is_boundary(eh)) continue;
    const int p0 = mesh.patch(tm.face_handle(tm.halfedge_handle(eh, 0)).idx());
    const int p1 = mesh.patch(tm.face_handle(tm.halfedge_handle(eh, 1)).idx());
    if (p0 != p1) neighbours[p0].push_back(p1), neighbours[p1].push_back(p0);
  }
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }

  const double cell =
      2.0 * std::sqrt(std::max(mesh.totalArea() / std::max(elementCount, 1), 1e-300));
  const double eps = 1e-9 * std::max(mesh.boundsDiagonal(), 1e-300);
  auto project = [&](const Frame& f, int e) {
    const auto c = mesh.corners(e);
    return Tri2{f.project(c[0]), f.project(c[1]), f.project(c[2])};
  };
  // A patch fits a chart when its triangles keep their winding and overlap no other patch's.
  auto fits = [&](const Frame& f, int p, const TriangleGrid& grid, const std::vector<Tri2>& tris,
                  const std::vector<int>& triPatch, std::vector<Tri2>& out) {
    out.clear();
    for (int e : patchElements[p]) {
      out.push_back(project(f, e));
      if (signedArea(out.back()) <= 0) return false;
    }
    for (const Tri2& t : out)
      if (grid.anyNear(
              t, [&](int id) { return triPatch[id] != p && trianglesOverlap2d(t, tris[id], eps); }))
        return false;
    return true;
  };

  std::vector<int> order(patchCount);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return patchArea[a] > patchArea[b]; });

  LightmapCharts result;
  result.chartOfElement.assign(elementCount, -1);
  result.corners.resize(elementCount);
  std::vector<int> chartOfPatch(patchCount, -1);
  std::vector<Tri2> scratch;
  for (int seed : order) {
    if (chartOfPatch[seed] >= 0 || patchElements[seed].empty()) continue;
    const int chartId = static_cast<int>(result.charts.size());
    const Frame seedFrame = frameFor(patchNormal[seed]);
    TriangleGrid grid(cell);
    std::vector<Tri2> tris;
    std::vector<int> triPatch, triElement, members;
    auto add = [&](int p, const std::vector<Tri2>& projected) {
      chartOfPatch[p] = chartId;
      members.push_back(p);
      for (size_t k = 0; k < projected.size(); ++k) {
        grid.insert(projected[k], static_cast<int>(tris.size()));
        tris.push_back(projected[k]);
        triPatch.push_back(p);
        triElement.push_back(patchElements[p][k]);
      }
    };
    // The seed is trusted: a patch is one planar polygon. (Its projection is its own plane.)
    scratch.clear();
    for (int e : patchElements[seed]) scratch.push_back(project(seedFrame, e));
    add(seed, scratch);
    std::queue<int> frontier;
    frontier.push(seed);
    while (!frontier.empty()) {
      const int p = frontier.front();
      frontier.pop();
      for (int q : neighbours[p]) {
        if (chartOfPatch[q] >= 0 || patchNormal[q].dot(patchNormal[seed]) < cosMax) continue;
        if (!fits(seedFrame, q, grid, tris, triPatch, scratch)) continue;
        add(q, scratch);
        frontier.push(q);
      }
    }

    // Prefer the average-normal plane (least distortion overall); keep the seed's plane, which
    // was checked patch by patch, if the average one would fold or overlap.
    Eigen::Vector3d avg = Eigen::Vector3d::Zero();
    for (int p : members) avg += patchArea[p] * patchNormal[p];
    LightmapChart chart;
    chart.normal = patchNormal[seed];
    if (members.size() > 1 && avg.norm() > 0) {
      const Frame avgFrame = frameFor(avg.normalized());
      TriangleGrid avgGrid(cell);
      std::vector<Tri2> avgTris;
      bool ok = true;
      for (size_t k = 0; k < tris.size() && ok; ++k) {
        const Tri2 t = project(avgFrame, triElement[k]);
        ok = signedArea(t) > 0 && !avgGrid.anyNear(t, [&](int id) {
          return triPatch[id] != triPatch[k] && trianglesOverlap2d(t, avgTris[id], eps);
        });
        avgGrid.insert(t, static_cast<int>(avgTris.size()));
        avgTris.push_back(t);
      }
      if (ok) tris.swap(avgTris), chart.normal = avg.normalized();
    }
    std::vector<Tri2*> pointers;
    for (auto& t : tris) pointers.push_back(&t);
    chart.size = orientChart(pointers);
    chart.patches = members;
    for (size_t k = 0; k < tris.size(); ++k) {
      const int e = triElement[k];
      result.chartOfElement[e] = chartId;
      result.corners[e] = tris[k];
      chart.elements.push_back(e);
    }
    result.charts.push_back(std::move(chart));
  }
  return result;
}

}  // namespace rad
