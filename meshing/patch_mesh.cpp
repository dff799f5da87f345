#include "meshing/patch_mesh.h"

#include <Eigen/Geometry>
#include <OpenMesh/Core/System/omstream.hh>
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

#include "meshing/polygon_triangulation.h"
#include "radiosity/core/check.h"

namespace rad {
namespace {
// Relative tolerance (on squared lengths) below which two edges count as equally long.
constexpr double kTie = 1e-7;
Eigen::Vector3d toEigen(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
OpenMesh::Vec3d toOm(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

PatchMesh::PatchMesh(const std::vector<Eigen::Vector3d>& positions,
                     const std::vector<PatchPolygon>& polygons) {
  // OpenMesh reports rejected (non-manifold) faces on its error stream; we handle them ourselves.
  omerr().disable();
  mesh_.add_property(patchId_, "patch");
  mesh_.add_property(materialId_, "material");
  mesh_.add_property(level_, "level");
  mesh_.add_property(shooterId_, "shooter");
  mesh_.add_property(area_, "area");

  for (const PatchPolygon& polygon : polygons) {
    RAD_CHECK_MSG(polygon.uvs.empty() || polygon.uvs.size() == polygon.vertices.size(),
                  "PatchMesh: a polygon needs one UV per corner");
    RAD_CHECK_MSG(
        polygon.lightmapUvs.empty() || polygon.lightmapUvs.size() == polygon.vertices.size(),
        "PatchMesh: a polygon needs one lightmap UV per corner");
  }
  const auto withUvs = std::count_if(polygons.begin(), polygons.end(),
                                     [](const PatchPolygon& p) { return !p.uvs.empty(); });
  const auto withLightmapUvs =
      std::count_if(polygons.begin(), polygons.end(),
                    [](const PatchPolygon& p) { return !p.uvs.empty() || !p.lightmapUvs.empty(); });
  anyUvs_ = withLightmapUvs > 0;
  allUvs_ = withUvs > 0 && withUvs == static_cast<long>(polygons.size());
  allLightmapUvs_ = anyUvs_ && withLightmapUvs == static_cast<long>(polygons.size());
  if (anyUvs_) mesh_.add_property(uvs_, "uv");

  std::vector<TriMesh::VertexHandle> handles(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) handles[i] = mesh_.add_vertex(toOm(positions[i]));

  boundsMin_ = Eigen::Vector3d::Constant(0);
  boundsMax_ = Eigen::Vector3d::Constant(0);
  bool first = true;
  for (const PatchPolygon& polygon : polygons) {
    std::vector<Eigen::Vector3d> points;
    for (int v : polygon.vertices) {
      RAD_CHECK_GE(v, 0);
      RAD_CHECK_LT(v, positions.size());
      points.push_back(positions[v]);
      if (first) {
        boundsMin_ = boundsMax_ = positions[v];
        first = false;
      }
      boundsMin_ = boundsMin_.cwiseMin(positions[v]);
      boundsMax_ = boundsMax_.cwiseMax(positions[v]);
    }
    const int patch = patchCount_++;
    const std::vector<Eigen::Vector2d>& lightmapSet =
        polygon.lightmapUvs.empty() ? polygon.uvs : polygon.lightmapUvs;
    auto cornersOf = [](const std::vector<Eigen::Vector2d>& set, const std::array<int, 3>& t) {
      return set.empty() ? std::array<Eigen::Vector2d, 3>{}
                         : std::array<Eigen::Vector2d, 3>{set[t[0]], set[t[1]], set[t[2]]};
    };
    for (const auto& t : triangulatePolygon(points)) {
      const std::array<Eigen::Vector2d, 3> uvs = cornersOf(polygon.uvs, t),
                                           lightmapUvs = cornersOf(lightmapSet, t);
      addTriangle(handles[polygon.vertices[t[0]]], handles[polygon.vertices[t[1]]],
                  handles[polygon.vertices[t[2]]], patch, polygon.material,
                  polygon.uvs.empty() ? nullptr : uvs.data(),
                  lightmapSet.empty() ? nullptr : lightmapUvs.data());
    }
  }
  inputTriangles_ = elementCount();
}

void PatchMesh::addTriangle(TriMesh::VertexHandle a, TriMesh::VertexHandle b,
                            TriMesh::VertexHandle c, int patch, int material,
                            const Eigen::Vector2d* uvs, const Eigen::Vector2d* lightmapUvs) {
  TriMesh::FaceHandle f = mesh_.add_face(a, b, c);
  if (!f.is_valid()) {
    // Non-manifold or inconsistently wound contact with a neighbour: give this triangle its own
    // vertices. It stays conforming within itself; the seam is a real crease in the input.
    // Copies: point() refers into OpenMesh's point array, which add_vertex() may reallocate.
    const TriMesh::Point pa = mesh_.point(a), pb = mesh_.point(b), pc = mesh_.point(c);
    a = mesh_.add_vertex(pa), b = mesh_.add_vertex(pb), c = mesh_.add_vertex(pc);
    f = mesh_.add_face(a, b, c);
    if (!f.is_valid()) throw std::runtime_error("PatchMesh: OpenMesh rejected a triangle");
  }
  if (anyUvs_) {
    FaceUvs& face = mesh_.property(uvs_, f);
    face = FaceUvs();
    face.vertex = {a.idx(), b.idx(), c.idx()};
    if (uvs)
      for (int k = 0; k < 3; ++k) face.uv[2 * k] = uvs[k].x(), face.uv[2 * k + 1] = uvs[k].y();
    if (lightmapUvs)
      for (int k = 0; k < 3; ++k)
        face.lightmapUv[2 * k] = lightmapUvs[k].x(),
                            face.lightmapUv[2 * k + 1] = lightmapUvs[k].y();
    face.valid = uvs != nullptr;
    face.lightmapValid = lightmapUvs != nullptr;
  }
  mesh_.property(patchId_, f) = patch;
  mesh_.property(materialId_, f) = material;
  mesh_.property(level_, f) = 0;
  mesh_.property(shooterId_, f) = 0;
  updateArea(f);
}

void PatchMesh::updateArea(TriMesh::FaceHandle f) {
  const auto c = corners(f.idx());
  mesh_.property(area_, f) = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
}

std::array<int, 3> PatchMesh::cornerVertices(int element) const {
  std::array<int, 3> v{};
  int k = 0;
  for (auto vh : mesh_.fv_range(face(element))) v[k++] = vh.idx();
  return v;
}

std::array<Eigen::Vector3d, 3> PatchMesh::corners(int element) const {
  std::array<Eigen::Vector3d, 3> c;
  int k = 0;
  for (auto vh : mesh_.fv_range(face(element))) c[k++] = toEigen(mesh_.point(vh));
  return c;
}

std::array<Eigen::Vector2d, 3> PatchMesh::cornerUvs(int element) const {
  RAD_CHECK_MSG(hasUvs(element), "PatchMesh::cornerUvs: the element has no UVs");
  return cornerSet(element, false);
}

std::array<Eigen::Vector2d, 3> PatchMesh::cornerLightmapUvs(int element) const {
  RAD_CHECK_MSG(anyUvs_ && mesh_.property(uvs_, face(element)).lightmapValid,
                "PatchMesh::cornerLightmapUvs: the element has no lightmap UVs");
  return cornerSet(element, true);
}

std::array<Eigen::Vector2d, 3> PatchMesh::cornerSet(int element, bool lightmap) const {
  const FaceUvs& face = mesh_.property(uvs_, this->face(element));
  const std::array<double, 6>& set = lightmap ? face.lightmapUv : face.uv;
  const std::array<int, 3> v = cornerVertices(element);
  std::array<Eigen::Vector2d, 3> uv;
  for (int k = 0; k < 3; ++k) {
    const int j = static_cast<int>(std::find(face.vertex.begin(), face.vertex.end(), v[k]) -
                                   face.vertex.begin());
    RAD_CHECK_MSG(j < 3, "PatchMesh::cornerUvs: UVs out of step with the faces");
    uv[k] = {set[2 * j], set[2 * j + 1]};
  }
  return uv;
}

Eigen::Vector3d PatchMesh::position(int vertex) const {
  return toEigen(mesh_.point(TriMesh::VertexHandle(vertex)));
}

Eigen::Vector3d PatchMesh::normal(int element) const {
  const auto c = corners(element);
  return (c[1] - c[0]).cross(c[2] - c[0]).normalized();
}

Eigen::Vector3d PatchMesh::centroid(int element) const {
  const auto c = corners(element);
  return (c[0] + c[1] + c[2]) / 3.0;
}

void PatchMesh::markShooters() {
  shooterCorners_.clear();
  for (int e = 0; e < elementCount(); ++e) {
    mesh_.property(shooterId_, face(e)) = e;
    shooterCorners_.push_back(corners(e));
  }
  shootersMarked_ = true;
}

double PatchMesh::shooterArea(int shooter) const {
  const auto c = shooterCorners(shooter);
  return 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
}

double PatchMesh::totalArea() const {
  double sum = 0;
  for (int e = 0; e < elementCount(); ++e) sum += area(e);
  return sum;
}

double PatchMesh::patchArea(int patch) const {
  double sum = 0;
  for (int e = 0; e < elementCount(); ++e)
    if (this->patch(e) == patch) sum += area(e);
  return sum;
}

TriMesh::EdgeHandle PatchMesh::longestEdge(TriMesh::FaceHandle f) const {
  // Lengths within kTie of the longest count as equal and the lowest edge index wins: rounding
  // must not decide between the equal legs of a bisected square, or the mesh would depend on the
  // scene's scale and position.
  double longest = 0;
  for (auto eh : mesh_.fe_range(f)) longest = std::max(longest, mesh_.calc_edge_sqr_length(eh));
  TriMesh::EdgeHandle best;
  for (auto eh : mesh_.fe_range(f))
    if (mesh_.calc_edge_sqr_length(eh) >= longest * (1 - kTie) &&
        (!best.is_valid() || eh.idx() < best.idx()))
      best = eh;
  return best;
}

void PatchMesh::splitEdge(TriMesh::EdgeHandle e) {
  const auto h = mesh_.halfedge_handle(e, 0);
  const int from = mesh_.from_vertex_handle(h).idx(), to = mesh_.to_vertex_handle(h).idx();
  const auto mid = mesh_.add_vertex(
      (mesh_.point(mesh_.from_vertex_handle(h)) + mesh_.point(mesh_.to_vertex_handle(h))) * 0.5);
  // split_copy gives each new face the properties (patch, material, level, UVs) of the face it
  // was cut from, so every face around the new vertex is a child one level below its parent.
  mesh_.split_copy(e, mid);
  for (auto f : mesh_.vf_range(mid)) {
    touched_.push_back(f.idx());
    mesh_.property(level_, f) += 1;
    updateArea(f);
    if (anyUvs_) splitUvs(f, from, to, mid.idx());
  }
}

void PatchMesh::splitUvs(TriMesh::FaceHandle f, int from, int to, int mid) {
  // The child still holds its parent's UVs: its corners are the parent's, except the new vertex
  // in the middle of the split edge, whose UV is the mean of that edge's two ends in the parent.
  const FaceUvs parent = mesh_.property(uvs_, f);
  auto parentUv = [&](const std::array<double, 6>& set, int vertex, int axis) {
    const int j = static_cast<int>(std::find(parent.vertex.begin(), parent.vertex.end(), vertex) -
                                   parent.vertex.begin());
    RAD_CHECK_MSG(j < 3, "PatchMesh: a split face lost its parent's corner");
    return set[2 * j + axis];
  };
  FaceUvs child;
  child.valid = parent.valid;
  child.lightmapValid = parent.lightmapValid;
  int k = 0;
  for (auto vh : mesh_.fv_range(f)) {
    child.vertex[k] = vh.idx();
    if (!parent.valid && !parent.lightmapValid) {  // a polygon without UVs: only the keys move
      ++k;
      continue;
    }
    for (int axis = 0; axis < 2; ++axis)
      for (auto [from_set, to_set] :
           {std::pair{&parent.uv, &child.uv}, std::pair{&parent.lightmapUv, &child.lightmapUv}})
        (*to_set)[2 * k + axis] =
            vh.idx() == mid
                ? 0.5 * (parentUv(*from_set, from, axis) + parentUv(*from_set, to, axis))
                : parentUv(*from_set, vh.idx(), axis);
    ++k;
  }
  mesh_.property(uvs_, f) = child;
}

void PatchMesh::refineAcross(TriMesh::FaceHandle f, int depth) {
  // Rivara's longest-edge propagation path: before splitting f's longest edge, make sure that
  // edge is also the longest of the face across it, refining that face first if not.
  for (int guard = 0; guard < 64; ++guard) {
    const TriMesh::EdgeHandle e = longestEdge(f);
    const double length = mesh_.calc_edge_sqr_length(e);
    const auto h = mesh_.halfedge_handle(e, 0);
    TriMesh::FaceHandle other = mesh_.face_handle(h);
    if (other == f) other = mesh_.opposite_face_handle(h);
    if (other.is_valid() && depth < 256) {
      const double otherLongest = mesh_.calc_edge_sqr_length(longestEdge(other));
      if (otherLongest > length * (1 + kTie)) {
        refineAcross(other, depth + 1);
        continue;  // the face across e changed; look again
      }
    }
    splitEdge(e);
    return;
  }
  splitEdge(longestEdge(f));
}

int PatchMesh::bisect(int element) {
  const int before = elementCount();
  touched_.clear();
  refineAcross(face(element), 0);
  return elementCount() - before;
}

void PatchMesh::subdivideUniform(double maxArea) {
  RAD_CHECK_GT(maxArea, 0.0);
  bool changed = true;
  while (changed) {
    changed = false;
    for (int e = 0; e < elementCount(); ++e) {
      while (area(e) > maxArea) {
        bisect(e);
        changed = true;
      }
    }
  }
}

void PatchMesh::subdivideToCount(int count) {
  // Largest first, from a heap whose stale entries (an element split since it was pushed) are
  // recognised by their key no longer matching. Areas are compared in steps of 2^-32 of the
  // total, the lowest index first among equals: rounding must not decide between congruent
  // elements, or the mesh would depend on the scene's scale and position.
  const double unit = totalArea() / 4294967296.0;
  const auto key = [&](int e) { return std::llround(area(e) / unit); };
  using Entry = std::pair<long long, int>;  // (area key, -element)
  std::priority_queue<Entry> largest;
  for (int e = 0; e < elementCount(); ++e) largest.push({key(e), -e});
  while (elementCount() < count && !largest.empty()) {
    const auto [k, minusE] = largest.top();
    largest.pop();
    if (k != key(-minusE)) continue;
    bisect(-minusE);
    for (int f : touched_) largest.push({key(f), -f});
  }
}

double PatchMesh::longestEdgeLength(int element) const {
  return std::sqrt(mesh_.calc_edge_sqr_length(longestEdge(face(element))));
}

double PatchMesh::aspectRatio(int element) const {
  const double longest = longestEdgeLength(element);
  const double a = area(element);
  return a > 0 ? longest * longest / (2 * a) : std::numeric_limits<double>::infinity();
}

}  // namespace rad
