#include "radiosity/scene/lightmap_uv_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "meshing/lightmap_charts.h"
#include "meshing/polygon_triangulation.h"
#include "radiosity/core/errors.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

using Tri2 = std::array<Eigen::Vector2d, 3>;

// UV space is the unit square whatever the scene's units, so absolute thresholds mean the same
// for every scene: far below one texel of the largest atlas (16384², texel area ~4e-9).
constexpr double kMinUvArea = 1e-14;
constexpr double kOverlapEps = 1e-9;

const char* const kOption = "--use-scene-uvs: ";

std::string uvText(const Eigen::Vector2d& uv) {
  std::ostringstream s;
  s << "(" << uv.x() << ", " << uv.y() << ")";
  return s.str();
}

double signedArea(const Tri2& t) {
  return 0.5 * ((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
}

struct UvTriangle {
  Tri2 uv;
  int polygon;
};

// Every polygon's triangles in UV, split the way the mesh splits them (PatchMesh uses the same
// triangulation), so the check sees exactly the triangles that will be baked.
std::vector<UvTriangle> uvTriangles(const Scene& scene) {
  const std::string& file = scene.sourcePath;
  int missing = 0, firstMissing = -1;
  for (size_t p = 0; p < scene.polygons.size(); ++p)
    if (bakeUvs(scene.polygons[p]).empty() && missing++ == 0) firstMissing = static_cast<int>(p);
  if (missing == static_cast<int>(scene.polygons.size()))
    throw InputError(file, 0,
                     std::string(kOption) +
                         "the scene has no texture coordinates ('vt' in its faces); leave the "
                         "option out to generate lightmap UVs");
  if (missing > 0)
    throw InputError(file, scene.polygons[firstMissing].sourceLine,
                     std::string(kOption) + "face lacks texture coordinates at some corner (" +
                         std::to_string(missing) + " of " + std::to_string(scene.polygons.size()) +
                         " faces lack them); every face needs them");

  std::vector<UvTriangle> triangles;
  for (size_t p = 0; p < scene.polygons.size(); ++p) {
    const ScenePolygon& polygon = scene.polygons[p];
    for (const Eigen::Vector2d& uv : bakeUvs(polygon))
      if (!(uv.x() >= 0 && uv.x() <= 1 && uv.y() >= 0 && uv.y() <= 1))
        throw InputError(file, polygon.sourceLine,
                         std::string(kOption) + "texture coordinate " + uvText(uv) +
                             " is outside [0, 1]: lightmap UVs may not tile");
    std::vector<Eigen::Vector3d> points;
    for (int v : polygon.vertices) points.push_back(scene.positions[v]);
    for (const auto& t : triangulatePolygon(points)) {
      const std::vector<Eigen::Vector2d>& uvs = bakeUvs(polygon);
      const Tri2 uv{uvs[t[0]], uvs[t[1]], uvs[t[2]]};
      if (std::abs(signedArea(uv)) <= kMinUvArea)
        throw InputError(file, polygon.sourceLine,
                         std::string(kOption) + "face has zero area in texture space (corners " +
                             uvText(uv[0]) + ", " + uvText(uv[1]) + ", " + uvText(uv[2]) +
                             "): it would own no texels");
      triangles.push_back({uv, static_cast<int>(p)});
    }
  }
  return triangles;
}

}  // namespace

void checkLightmapUvs(const Scene& scene) {
  const std::vector<UvTriangle> triangles = uvTriangles(scene);
  // A uniform grid over the unit square; a pair of triangles is tested once, in the first cell
  // their bounding boxes share.
  const int cells = std::clamp(static_cast<int>(std::ceil(std::sqrt(triangles.size()))), 1, 2048);
  auto cellRange = [&](const Tri2& t, int& x0, int& y0, int& x1, int& y1) {
    const Eigen::Vector2d lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
    const Eigen::Vector2d hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    auto cell = [&](double x) { return std::clamp(static_cast<int>(x * cells), 0, cells - 1); };
    x0 = cell(lo.x()), y0 = cell(lo.y()), x1 = cell(hi.x()), y1 = cell(hi.y());
  };
  std::vector<std::vector<int>> grid(static_cast<size_t>(cells) * cells);
  for (size_t i = 0; i < triangles.size(); ++i) {
    int x0, y0, x1, y1;
    cellRange(triangles[i].uv, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) grid[static_cast<size_t>(y) * cells + x].push_back(int(i));
  }
  for (int y = 0; y < cells; ++y)
    for (int x = 0; x < cells; ++x) {
      const std::vector<int>& here = grid[static_cast<size_t>(y) * cells + x];
      for (size_t a = 0; a < here.size(); ++a)
        for (size_t b = a + 1; b < here.size(); ++b) {
          const UvTriangle& ta = triangles[here[a]];
          const UvTriangle& tb = triangles[here[b]];
          int ax0, ay0, ax1, ay1, bx0, by0, bx1, by1;
          cellRange(ta.uv, ax0, ay0, ax1, ay1);
          cellRange(tb.uv, bx0, by0, bx1, by1);
          if (std::max(ax0, bx0) != x || std::max(ay0, by0) != y) continue;  // tested elsewhere
          if (!trianglesOverlap2d(ta.uv, tb.uv, kOverlapEps)) continue;
          const ScenePolygon& first = scene.polygons[std::min(ta.polygon, tb.polygon)];
          const ScenePolygon& second = scene.polygons[std::max(ta.polygon, tb.polygon)];
          if (ta.polygon == tb.polygon)
            throw InputError(scene.sourcePath, first.sourceLine,
                             std::string(kOption) +
                                 "face folds over itself in texture space (two of its triangles "
                                 "overlap)");
          throw InputError(scene.sourcePath, second.sourceLine,
                           std::string(kOption) + "face overlaps the face at line " +
                               std::to_string(first.sourceLine) +
                               " in texture space: lightmap UVs need every face its own texels");
        }
    }
}

}  // namespace rad
