#include "meshing/polygon_triangulation.h"

#include <cmath>
#include <numeric>

namespace rad {

Eigen::Vector3d newellNormal(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector3d& a = p[i];
    const Eigen::Vector3d& b = p[(i + 1) % p.size()];
    n.x() += (a.y() - b.y()) * (a.z() + b.z());
    n.y() += (a.z() - b.z()) * (a.x() + b.x());
    n.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  return n;
}

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Eigen::Vector3d>& polygon) {
  std::vector<std::array<int, 3>> triangles;
  const int n = static_cast<int>(polygon.size());
  if (n < 3) return triangles;
  if (n == 3) return {{0, 1, 2}};

  // Project onto the plane perpendicular to the dominant axis of the normal.
  const Eigen::Vector3d normal = newellNormal(polygon);
  int drop = 0;
  normal.cwiseAbs().maxCoeff(&drop);
  const int ax = (drop + 1) % 3, ay = (drop + 2) % 3;
  const double orientation = normal[drop] >= 0 ? 1.0 : -1.0;
  auto cross2 = [&](int a, int b, int c) {
    const Eigen::Vector3d &pa = polygon[a], &pb = polygon[b], &pc = polygon[c];
    return orientation *
           ((pb[ax] - pa[ax]) * (pc[ay] - pa[ay]) - (pb[ay] - pa[ay]) * (pc[ax] - pa[ax]));
  };
  // Closed test: a vertex on the ear's border (e.g. a reflex corner touching the diagonal) also
  // blocks it, unless it coincides with one of the ear's own corners.
  auto inside = [&](int a, int b, int c, int p) {
    if (polygon[p] == polygon[a] || polygon[p] == polygon[b] || polygon[p] == polygon[c])
      return false;
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
  };

  std::vector<int> ring(n);
  std::iota(ring.begin(), ring.end(), 0);
  int guard = 0;
  while (ring.size() > 3 && guard < 4 * n * n) {
    bool clipped = false;
    const int m = static_cast<int>(ring.size());
    for (int i = 0; i < m; ++i) {
      const int a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
      ++guard;
      if (cross2(a, b, c) <= 0) continue;  // reflex or degenerate corner
      bool blocked = false;
      for (int q : ring)
        if (q != a && q != b && q != c && inside(a, b, c, q)) {
          blocked = true;
          break;
        }
      if (blocked) continue;
      triangles.push_back({a, b, c});
      ring.erase(ring.begin() + i);
      clipped = true;
      break;
    }
    if (!clipped) {
      // Self-intersecting or collinear input: fall back to a fan over what is left.
      for (size_t i = 1; i + 1 < ring.size(); ++i)
        triangles.push_back({ring[0], ring[i], ring[i + 1]});
      return triangles;
    }
  }
  if (ring.size() == 3) triangles.push_back({ring[0], ring[1], ring[2]});
  return triangles;
}

}  // namespace rad
