// Slivers into well-shaped elements: longest-edge bisection plus Delaunay flips inside patches.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include "meshing/patch_mesh.h"
#include "radiosity/core/check.h"

namespace rad {
namespace {
Eigen::Vector3d toEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }

// Two faces count as one plane when their unit normals agree this closely (a flip across a
// crease would move the surface).
constexpr double kCoplanar = 1e-10;
// A flip must beat the Delaunay criterion by this margin (radians), so that four points on one
// circle (a square's two diagonals) never flip back and forth.
constexpr double kDelaunayMargin = 1e-9;
// Rounds of bisection and flips. Each round halves the longest edge of every sliver left, so
// this bounds the length ratio fixed at 2^64: the bound is a guard, not a setting.
constexpr int kMaxRounds = 64;

double angleAt(const Eigen::Vector3d& apex, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - apex, v = b - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}
}  // namespace

bool PatchMesh::shouldFlip(TriMesh::EdgeHandle e) const {
  if (mesh_.is_boundary(e)) return false;
  const auto h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
  const auto f0 = mesh_.face_handle(h0), f1 = mesh_.face_handle(h1);
  if (mesh_.property(patchId_, f0) != mesh_.property(patchId_, f1)) return false;
  if (!mesh_.is_flip_ok(e)) return false;
  const Eigen::Vector3d a = toEigen(mesh_.point(mesh_.from_vertex_handle(h0)));
  const Eigen::Vector3d b = toEigen(mesh_.point(mesh_.to_vertex_handle(h0)));
  const Eigen::Vector3d c =
      toEigen(mesh_.point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h0))));
  const Eigen::Vector3d d =
      toEigen(mesh_.point(mesh_.to_vertex_handle(mesh_.next_halfedge_handle(h1))));
  const Eigen::Vector3d n0 = (b - a).cross(c - a), n1 = (a - b).cross(d - b);
  if (n0.normalized().dot(n1.normalized()) < 1 - kCoplanar) return false;
  // The flipped pair (c, a, d) and (d, b, c) must face the same way with area: the quad is
  // convex.
  const Eigen::Vector3d m0 = (a - c).cross(d - c), m1 = (b - d).cross(c - d);
  const double tiny = 1e-12 * n0.norm();
  if (m0.dot(n0) <= tiny || m1.dot(n0) <= tiny) return false;
  return angleAt(c, a, b) + angleAt(d, a, b) > M_PI + kDelaunayMargin;
}

void PatchMesh::flipEdge(TriMesh::EdgeHandle e) {
  const auto h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
  const auto f0 = mesh_.face_handle(h0), f1 = mesh_.face_handle(h1);
  // Both faces lie in one patch, where a vertex has one UV: keep them by vertex across the flip.
  std::map<int, std::array<double, 4>> uvOf;  // texture (u, v), lightmap (u, v)
  const FaceUvs before = anyUvs_ ? mesh_.property(uvs_, f0) : FaceUvs();
  if (anyUvs_)
    for (auto f : {f0, f1}) {
      const FaceUvs& face = mesh_.property(uvs_, f);
      for (int k = 0; k < 3; ++k)
        uvOf[face.vertex[k]] = {face.uv[2 * k], face.uv[2 * k + 1], face.lightmapUv[2 * k],
                                face.lightmapUv[2 * k + 1]};
    }
  const int level = std::max(mesh_.property(level_, f0), mesh_.property(level_, f1));
  mesh_.flip(e);
  for (auto f : {f0, f1}) {
    touched_.push_back(f.idx());
    mesh_.property(level_, f) = level;
    updateArea(f);
    if (!anyUvs_) continue;
    FaceUvs face;
    face.valid = before.valid;
    face.lightmapValid = before.lightmapValid;
    int k = 0;
    for (auto vh : mesh_.fv_range(f)) {
      face.vertex[k] = vh.idx();
      if (!face.valid && !face.lightmapValid) {  // a polygon without UVs: only the keys move
        ++k;
        continue;
      }
      const auto uv = uvOf.find(vh.idx());
      RAD_CHECK_MSG(uv != uvOf.end(), "PatchMesh: a flipped face gained an unknown corner");
      face.uv[2 * k] = uv->second[0], face.uv[2 * k + 1] = uv->second[1];
      face.lightmapUv[2 * k] = uv->second[2], face.lightmapUv[2 * k + 1] = uv->second[3];
      ++k;
    }
    mesh_.property(uvs_, f) = face;
  }
}

int PatchMesh::flipToDelaunay() {
  // Lawson's algorithm: each flip raises the triangulation's smallest angles, so it ends; the
  // guard only catches a bug.
  std::deque<TriMesh::EdgeHandle> pending(mesh_.edges_begin(), mesh_.edges_end());
  int flips = 0;
  const long guard = 64L * static_cast<long>(mesh_.n_edges()) + 1024;
  for (long step = 0; !pending.empty() && step < guard; ++step) {
    const TriMesh::EdgeHandle e = pending.front();
    pending.pop_front();
    if (!shouldFlip(e)) continue;
    flipEdge(e);
    ++flips;
    // The quad's four outer edges may no longer be Delaunay.
    for (auto h : {mesh_.halfedge_handle(e, 0), mesh_.halfedge_handle(e, 1)})
      for (auto g : {mesh_.next_halfedge_handle(h), mesh_.prev_halfedge_handle(h)})
        pending.push_back(mesh_.edge_handle(g));
  }
  return flips;
}

bool PatchMesh::isPatchBorder(TriMesh::EdgeHandle e) const {
  if (mesh_.is_boundary(e)) return true;
  const auto f0 = mesh_.face_handle(mesh_.halfedge_handle(e, 0));
  const auto f1 = mesh_.face_handle(mesh_.halfedge_handle(e, 1));
  return mesh_.property(patchId_, f0) != mesh_.property(patchId_, f1) ||
         normal(f0.idx()).dot(normal(f1.idx())) < 1 - kCoplanar;
}

bool PatchMesh::splitSliver(int element) {
  // Only edges on the patch's outline are split. A sliver's longest edge inside a Delaunay patch
  // is a diagonal across the thin strip: its midpoint would be a vertex inside the strip, off
  // both of its sides, and the Delaunay triangles around such vertices are slivers again (the
  // count then grows without the shapes improving). Points on the outline instead let the flips
  // make short pieces. The edge is split on its own, not by Rivara's propagation (which would
  // bisect the longer diagonals beyond it): any edge split keeps the mesh conforming, as both
  // faces beside it are split.
  TriMesh::EdgeHandle border;
  double borderLength = 0;
  for (auto e : mesh_.fe_range(face(element))) {
    const double length = mesh_.calc_edge_sqr_length(e);
    if (isPatchBorder(e) && length > borderLength) border = e, borderLength = length;
  }
  const double longest = longestEdgeLength(element);
  if (!border.is_valid() || borderLength < 0.25 * longest * longest) return false;
  splitEdge(border);
  return true;
}

void PatchMesh::splitSlivers(double maxAspect, double minEdge) {
  RAD_CHECK_GT(maxAspect, 2.0);  // halves of a square are 2: a lower bound cannot be met
  RAD_CHECK_GE(minEdge, 0.0);
  const auto isSliver = [&](int e) {
    return aspectRatio(e) > maxAspect && longestEdgeLength(e) > minEdge;
  };
  for (int round = 0; round < kMaxRounds; ++round) {
    flipToDelaunay();
    std::vector<int> slivers;
    for (int e = 0; e < elementCount(); ++e)
      if (isSliver(e)) slivers.push_back(e);
    if (slivers.empty()) break;
    // A split for one sliver may already have split another: test again. A sliver without an
    // outline edge to split waits for its neighbours' splits and flips to change it.
    int splits = 0;
    for (int e : slivers)
      if (isSliver(e)) splits += splitSliver(e);
    if (splits == 0) break;
  }
  touched_.clear();
}

}  // namespace rad
