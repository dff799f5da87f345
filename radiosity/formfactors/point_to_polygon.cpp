#include "radiosity/formfactors/point_to_polygon.h"

#include <Eigen/Geometry>
#include <cmath>

#include "meshing/polygon_triangulation.h"

namespace rad {
namespace {

// Sutherland–Hodgman against the plane n·(x − p) >= 0.
std::vector<Eigen::Vector3d> clipAbove(const std::vector<Eigen::Vector3d>& polygon,
                                       const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                       double tolerance) {
  std::vector<Eigen::Vector3d> out;
  const size_t m = polygon.size();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d& a = polygon[i];
    const Eigen::Vector3d& b = polygon[(i + 1) % m];
    double da = n.dot(a - p), db = n.dot(b - p);
    if (std::fabs(da) <= tolerance) da = 0;
    if (std::fabs(db) <= tolerance) db = 0;
    if (da >= 0) out.push_back(a);
    if ((da > 0 && db < 0) || (da < 0 && db > 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

}  // namespace

double pointToPolygonFormFactor(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                                const std::vector<Eigen::Vector3d>& polygon) {
  if (polygon.size() < 3) return 0.0;
  const Eigen::Vector3d polygonNormal = newellNormal(polygon);  // |·| = twice the area
  const double twiceArea = polygonNormal.norm();
  if (!(twiceArea > 0)) return 0.0;
  const Eigen::Vector3d sourceNormal = polygonNormal / twiceArea;
  double scale = 0;
  for (const auto& v : polygon) scale = std::max(scale, (v - p).norm());
  if (!(scale > 0)) return 0.0;
  // One-sided: p must be in front of the polygon's plane. A p in that plane (on a shared edge)
  // counts as just in front, unless the two are coplanar, which never exchange light.
  const double height = sourceNormal.dot(p - polygon[0]);
  if (height < -1e-12 * scale) return 0.0;
  if (height <= 1e-12 * scale && std::fabs(sourceNormal.dot(n)) > 1 - 1e-9) return 0.0;

  const std::vector<Eigen::Vector3d> visible = clipAbove(polygon, p, n, 1e-12 * scale);
  if (visible.size() < 3) return 0.0;

  // Direction, in p's tangent plane, towards the side the source faces: the side from which p
  // approaches an edge it lies on.
  Eigen::Vector3d approach = sourceNormal - sourceNormal.dot(n) * n;
  const double approachNorm = approach.norm();
  if (approachNorm > 0) approach /= approachNorm;

  double sum = 0;
  const size_t m = visible.size();
  for (size_t i = 0; i < m; ++i) {
    const Eigen::Vector3d a = visible[i] - p, b = visible[(i + 1) % m] - p;
    const double la = a.norm(), lb = b.norm();
    if (la <= 1e-14 * scale || lb <= 1e-14 * scale) continue;  // p at a vertex: no angle to add
    const Eigen::Vector3d cross = a.cross(b);
    const double crossNorm = cross.norm();
    const double beta = std::atan2(crossNorm, a.dot(b));
    if (crossNorm > 1e-12 * la * lb) {
      sum += beta * n.dot(cross / crossNorm);
    } else if (a.dot(b) < 0 && approachNorm > 0) {
      // p on this edge: limit of unit(R_a × R_b) as p moves off the edge by ε·approach is
      // unit(approach × (v_a − v_b)); β → π.
      const Eigen::Vector3d limit = approach.cross(a - b).normalized();
      sum += M_PI * n.dot(limit);
    }
  }
  // The contour's orientation follows the winding; the front-facing check above fixed which side
  // sees it, so the magnitude is the form factor.
  return std::fabs(sum) / (2.0 * M_PI);
}

}  // namespace rad
