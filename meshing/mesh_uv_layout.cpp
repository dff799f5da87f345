#include "meshing/mesh_uv_layout.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {
namespace {

// UVs that agree this closely (UV space is the unit square) are the same point: bisection
// averages the same two numbers on both sides of an edge, so shared UVs stay bitwise equal; the
// tolerance only forgives UVs written out with rounding.
constexpr double kSameUv = 1e-12;

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

double uvArea(const std::array<Eigen::Vector2d, 3>& t) {
  return 0.5 *
         std::abs((t[1] - t[0]).x() * (t[2] - t[0]).y() - (t[1] - t[0]).y() * (t[2] - t[0]).x());
}

// The UV the element gives to one of its corner vertices.
Eigen::Vector2d uvAt(const PatchMesh& mesh, int element, int vertex) {
  const std::array<int, 3> v = mesh.cornerVertices(element);
  const std::array<Eigen::Vector2d, 3> uv = mesh.cornerLightmapUvs(element);
  for (int k = 0; k < 3; ++k)
    if (v[k] == vertex) return uv[k];
  RAD_CHECK_MSG(false, "uvAt: the vertex is not a corner of the element");
  return {};
}

}  // namespace

LightmapLayout layoutFromMeshUvs(const PatchMesh& mesh, int width, int height, int padding) {
  RAD_CHECK_MSG(mesh.hasLightmapUvs(), "layoutFromMeshUvs: the mesh has no lightmap UVs");
  RAD_CHECK_GE(width, 1);
  RAD_CHECK_GE(height, 1);
  const int elements = mesh.elementCount();
  std::vector<int> parent(elements);
  std::iota(parent.begin(), parent.end(), 0);
  auto join = [&](int a, int b) { parent[findRoot(parent, a)] = findRoot(parent, b); };

  std::vector<int> firstOfPatch(mesh.patchCount(), -1);
  for (int e = 0; e < elements; ++e) {
    int& first = firstOfPatch[mesh.patch(e)];
    if (first < 0) first = e;
    join(e, first);
  }
  const TriMesh& tm = mesh.mesh();
  for (auto eh : tm.edges()) {
    if (tm.is_boundary(eh)) continue;
    const auto h = tm.halfedge_handle(eh, 0);
    const int f0 = tm.face_handle(h).idx(), f1 = tm.opposite_face_handle(h).idx();
    const int a = tm.from_vertex_handle(h).idx(), b = tm.to_vertex_handle(h).idx();
    if ((uvAt(mesh, f0, a) - uvAt(mesh, f1, a)).cwiseAbs().maxCoeff() <= kSameUv &&
        (uvAt(mesh, f0, b) - uvAt(mesh, f1, b)).cwiseAbs().maxCoeff() <= kSameUv)
      join(f0, f1);
  }

  LightmapLayout layout;
  layout.width = width, layout.height = height, layout.padding = padding;
  layout.chartOfElement.assign(elements, -1);
  layout.texels.resize(elements);
  std::vector<int> chartOfRoot(elements, -1);
  double surfaceArea = 0, texelArea = 0;
  for (int e = 0; e < elements; ++e) {
    int& chart = chartOfRoot[findRoot(parent, e)];
    if (chart < 0) {
      chart = static_cast<int>(layout.rects.size());
      layout.rects.push_back({width, height, 0, 0, false});  // grown below
    }
    layout.chartOfElement[e] = chart;
    const std::array<Eigen::Vector2d, 3> uv = mesh.cornerLightmapUvs(e);
    for (int k = 0; k < 3; ++k)
      layout.texels[e][k] = Eigen::Vector2d(uv[k].x() * width, (1 - uv[k].y()) * height);
    surfaceArea += mesh.area(e);
    texelArea += uvArea(layout.texels[e]);

    // The chart's rectangle: every texel its elements touch. Stored as (x0, y0, x1, y1) until
    // the end, then turned into (x, y, width, height).
    ChartRect& r = layout.rects[chart];
    for (const Eigen::Vector2d& t : layout.texels[e]) {
      r.x = std::min(r.x, std::clamp(static_cast<int>(std::floor(t.x())), 0, width - 1));
      r.y = std::min(r.y, std::clamp(static_cast<int>(std::floor(t.y())), 0, height - 1));
      r.width = std::max(r.width, std::clamp(static_cast<int>(std::ceil(t.x())), 1, width));
      r.height = std::max(r.height, std::clamp(static_cast<int>(std::ceil(t.y())), 1, height));
    }
  }
  for (ChartRect& r : layout.rects) r.width -= r.x, r.height -= r.y;
  layout.texelSize = texelArea > 0 ? std::sqrt(surfaceArea / texelArea) : 0;
  return layout;
}

int atlasSideForTexelSize(const PatchMesh& mesh, double texelSize, int maxSide) {
  RAD_CHECK_GT(texelSize, 0.0);
  double surfaceArea = 0, uvTotal = 0;
  for (int e = 0; e < mesh.elementCount(); ++e)
    surfaceArea += mesh.area(e), uvTotal += uvArea(mesh.cornerLightmapUvs(e));
  const double side = std::ceil(std::sqrt(surfaceArea / uvTotal) / texelSize);
  if (!(side <= maxSide))
    throw InputError("texel size " + std::to_string(texelSize) + " needs a lightmap larger than " +
                     std::to_string(maxSide) +
                     " texels in the scene's UVs; use a larger --texel-size");
  return std::max(8, static_cast<int>(side));
}

}  // namespace rad
