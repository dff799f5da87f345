#include "radiosity/visibility/element_exposure.h"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {
namespace {

constexpr uint64_t kAllCells = ~uint64_t{0};

}  // namespace

std::array<Eigen::Vector3d, 4> ElementExposure::probeDirections(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::fabs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d t = n.cross(helper).normalized(), b = n.cross(t);
  std::array<Eigen::Vector3d, 4> d;
  d[0] = n;
  for (int k = 0; k < 3; ++k) {
    const double phi = 2 * M_PI * k / 3;
    d[k + 1] = (std::sqrt(0.75) * (std::cos(phi) * t + std::sin(phi) * b) + 0.5 * n).normalized();
  }
  return d;
}

namespace {

struct Prober {
  const RayCaster& rays;
  const std::vector<Eigen::Vector3d>& normals;  // per element, PatchMesh::normal (once each)

  // Every probe from the point at (s, t) of element e (corners c) hits the back of a surface.
  bool buriedAt(int e, const std::array<Eigen::Vector3d, 3>& c, double s, double t,
                const std::array<Eigen::Vector3d, 4>& directions, uint64_t& cast) const {
    const Eigen::Vector2d w = triangleWeights(s, t);
    const Eigen::Vector3d p = c[0] + w[0] * (c[1] - c[0]) + w[1] * (c[2] - c[0]);
    const Eigen::Vector3d n = directions[0];
    const Eigen::Vector3d origin = rays.liftOff(p, n, n);
    for (const Eigen::Vector3d& d : directions) {
      ++cast;
      const RayHit hit = rays.closestHit(origin, d);
      if (!hit.hit() || hit.element == e || normals[static_cast<size_t>(hit.element)].dot(d) < 0)
        return false;
    }
    return true;
  }
};

}  // namespace

ElementExposure::ElementExposure(const PatchMesh& mesh, const RayCaster& rays)
    : ElementExposure(mesh, rays, {}, {}) {}

ElementExposure::ElementExposure(const PatchMesh& mesh, const RayCaster& rays,
                                 const std::vector<uint64_t>& known,
                                 const std::vector<char>& isKnown) {
  const int n = mesh.elementCount();
  RAD_CHECK(isKnown.empty() ||
            (isKnown.size() == static_cast<size_t>(n) && known.size() == isKnown.size()));
  buried_.assign(n, 0);
  std::vector<uint64_t> cast(n, 0);
  // A probe's hit needs the normal of what it hit: computed once per element, not per probe (it
  // walks the element's corners in the OpenMesh structure).
  std::vector<Eigen::Vector3d> normals(static_cast<size_t>(n));
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 1024), [&](const tbb::blocked_range<int>& r) {
    for (int e = r.begin(); e < r.end(); ++e) normals[static_cast<size_t>(e)] = mesh.normal(e);
  });
  const Prober prober{rays, normals};
  constexpr double kCell = 1.0 / kGrid;
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 16), [&](const tbb::blocked_range<int>& range) {
    for (int e = range.begin(); e < range.end(); ++e) {
      if (!isKnown.empty() && isKnown[static_cast<size_t>(e)]) {
        buried_[e] = known[static_cast<size_t>(e)];
        continue;
      }
      const auto directions = probeDirections(normals[static_cast<size_t>(e)]);
      const auto corners = mesh.corners(e);
      // The 4×4 blocks, each probed at its centre (a corner shared by its four cells).
      uint64_t cells = 0;
      for (int by = 0; by < kGrid / 2; ++by)
        for (int bx = 0; bx < kGrid / 2; ++bx) {
          if (!prober.buriedAt(e, corners, (2 * bx + 1) * kCell, (2 * by + 1) * kCell, directions,
                               cast[e]))
            continue;
          for (int y = 2 * by; y < 2 * by + 2; ++y)
            for (int x = 2 * bx; x < 2 * bx + 2; ++x) cells |= uint64_t{1} << (y * kGrid + x);
        }
      if (cells != 0 && cells != kAllCells) {  // an edge crosses the element: every cell
        cells = 0;
        for (int y = 0; y < kGrid; ++y)
          for (int x = 0; x < kGrid; ++x)
            if (prober.buriedAt(e, corners, (x + 0.5) * kCell, (y + 0.5) * kCell, directions,
                                cast[e]))
              cells |= uint64_t{1} << (y * kGrid + x);
      }
      buried_[e] = cells;
    }
  });
  for (int e = 0; e < n; ++e) probeRays_ += cast[e];
  summarise(mesh);
}

ElementExposure::ElementExposure(const PatchMesh& mesh, std::vector<uint64_t> buriedCells)
    : buried_(std::move(buriedCells)) {
  RAD_CHECK_EQ(buried_.size(), static_cast<size_t>(mesh.elementCount()));
  summarise(mesh);
}

void ElementExposure::summarise(const PatchMesh& mesh) {
  for (int e = 0; e < static_cast<int>(buried_.size()); ++e) {
    const int count = __builtin_popcountll(buried_[e]);
    partly_ += count > 0 && count < kGrid * kGrid;
    fully_ += count == kGrid * kGrid;
    buriedArea_ += mesh.area(e) * count / (kGrid * kGrid);
  }
  if (partly_ == 0 && fully_ == 0) buried_.clear();  // nothing buried: every query is trivial
}

std::vector<uint64_t> ElementExposure::allBuriedCells(int elements) const {
  if (buried_.empty()) return std::vector<uint64_t>(elements, 0);
  RAD_CHECK_EQ(buried_.size(), static_cast<size_t>(elements));
  return buried_;
}

double ElementExposure::exposedFraction(int e) const {
  if (buried_.empty()) return 1;
  const double exposed = 1.0 - __builtin_popcountll(buried_[e]) / double(kGrid * kGrid);
  return std::max(exposed, kMinFraction);
}

bool ElementExposure::buried(int e, double s, double t) const {
  if (buried_.empty() || buried_[e] == 0) return false;
  const int x = std::clamp(static_cast<int>(s * kGrid), 0, kGrid - 1);
  const int y = std::clamp(static_cast<int>(t * kGrid), 0, kGrid - 1);
  return (buried_[e] >> (y * kGrid + x)) & 1;
}

bool ElementExposure::buriedAtBarycentric(int e, double w1, double w2) const {
  if (buried_.empty() || buried_[e] == 0) return false;
  const double r = w1 + w2;  // √s
  return buried(e, r * r, r > 0 ? w2 / r : 0.0);
}

bool ElementExposure::buriedAtPoint(const PatchMesh& mesh, int e, const Eigen::Vector3d& p) const {
  if (buried_.empty() || buried_[e] == 0) return false;
  if (buried_[e] == ~uint64_t(0)) return true;  // fully buried: anywhere on it
  // Barycentrics of p's projection onto the triangle's plane (a hit lies on it up to rounding),
  // clamped onto the triangle: a hit on an edge may round a little outside.
  const auto c = mesh.corners(e);
  const Eigen::Vector3d e1 = c[1] - c[0], e2 = c[2] - c[0], v = p - c[0];
  const double d11 = e1.dot(e1), d12 = e1.dot(e2), d22 = e2.dot(e2);
  const double v1 = v.dot(e1), v2 = v.dot(e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return false;  // degenerate: no cells to speak of
  double w1 = std::max(0.0, (d22 * v1 - d12 * v2) / det);
  double w2 = std::max(0.0, (d11 * v2 - d12 * v1) / det);
  if (w1 + w2 > 1) {
    const double sum = w1 + w2;
    w1 /= sum;
    w2 /= sum;
  }
  return buriedAtBarycentric(e, w1, w2);
}

Eigen::Vector2d ElementExposure::exposedPoint(int e) const {
  const uint64_t cells = buriedCells(e);
  int cell = 0;
  while (cell < kGrid * kGrid && ((cells >> cell) & 1)) ++cell;
  if (cell == kGrid * kGrid) cell = 0;  // all buried: any point is as good
  return triangleWeights((cell % kGrid + 0.5) / kGrid, (cell / kGrid + 0.5) / kGrid);
}

}  // namespace rad
