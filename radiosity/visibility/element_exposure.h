#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Which parts of each element are buried: enclosed by one-sided geometry or under a surface lying
// on it (the floor under a box standing on it, the end of a beam inside a wall). No light reaches
// a buried point and none leaves it, in the path tracer as in reality. Yet an element straddling
// the edge of a box would spread what it receives over its whole area and shoot from all of it,
// and the rays from its buried part would hit the box from inside and be lost: a loss that grows
// with the element size (measured on the Cornell box: total power 0.8% low at 200 elements,
// 0.1% at 24,000). So the solve uses each element's exposed area, and shoots and samples light
// only from its exposed part (docs/physics.md, "Buried parts of elements").
//
// A point is buried when every probe ray from it (along the normal and three 60° off it) hits
// the back of a surface: it sees no front face and no sky. Two-sided surfaces are seen from both
// sides, so a point under a two-sided box counts as exposed. Each element is probed on an 8×8
// grid of equal-area cells over its triangle, in the unit-square coordinates (s, t) of
// uniformPointOnTriangle (barycentrics w1 = √s (1 − t), w2 = √s t of corners 1 and 2): first at
// the centres of its 4×4 blocks of cells, then in every cell where the blocks disagree.
class ElementExposure {
 public:
  static constexpr int kGrid = 8;
  // The least exposed fraction an element keeps, so that values per unit area stay finite.
  static constexpr double kMinFraction = 1.0 / (2 * kGrid * kGrid);

  ElementExposure() = default;  // nothing buried anywhere
  ElementExposure(const PatchMesh& mesh, const RayCaster& rays);
  // The same, with the elements where isKnown[e] taking known[e] without a probe (update: the
  // elements whose probe rays cannot meet the edit). Both empty, or one per element.
  ElementExposure(const PatchMesh& mesh, const RayCaster& rays, const std::vector<uint64_t>& known,
                  const std::vector<char>& isKnown);
  // As found before (elements.csv's buried_cells column): one mask per element, no ray cast.
  ElementExposure(const PatchMesh& mesh, std::vector<uint64_t> buriedCells);

  // The probe directions of an element with front normal n: n and three 60° off it, 120° apart.
  static std::array<Eigen::Vector3d, 4> probeDirections(const Eigen::Vector3d& n);

  // Bit y·8 + x set: cell x (along s), y (along t) of element e is buried.
  uint64_t buriedCells(int e) const { return buried_.empty() ? 0 : buried_[e]; }
  // buriedCells(e) for every one of the mesh's `elements`, as elements.csv keeps them.
  std::vector<uint64_t> allBuriedCells(int elements) const;
  // The exposed share of element e's area, at least kMinFraction.
  double exposedFraction(int e) const;
  bool buried(int e, double s, double t) const;
  bool buriedAtBarycentric(int e, double w1, double w2) const;
  // Whether point p of element e's plane (a ray's hit on it) lies in one of its buried cells: no
  // light reaches it there (a ray slipping through the crack where a box meets the floor).
  bool buriedAtPoint(const PatchMesh& mesh, int e, const Eigen::Vector3d& p) const;
  // Barycentrics (w1, w2) of the centre of an exposed cell of e (the first in cell order).
  Eigen::Vector2d exposedPoint(int e) const;

  int partlyBuried() const { return partly_; }  // some cells buried, not all
  int fullyBuried() const { return fully_; }
  double buriedArea() const { return buriedArea_; }  // scene units²
  uint64_t probeRays() const { return probeRays_; }

 private:
  void summarise(const PatchMesh& mesh);  // the counts and area from buried_

  std::vector<uint64_t> buried_;
  int partly_ = 0, fully_ = 0;
  double buriedArea_ = 0;
  uint64_t probeRays_ = 0;
};

// Barycentrics (w1, w2) of corners 1 and 2 at unit-square coordinates (s, t), and back.
inline Eigen::Vector2d triangleWeights(double s, double t) {
  const double r = std::sqrt(s);
  return {r * (1 - t), r * t};
}

}  // namespace rad
