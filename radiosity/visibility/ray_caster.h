#pragma once

#include <embree3/rtcore.h>

#include <Eigen/Core>
#include <array>
#include <limits>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/scene/coverage.h"
#include "radiosity/scene/scene.h"

namespace rad {

struct RayHit {
  int element = -1;  // -1: the ray left the scene
  double distance = std::numeric_limits<double>::infinity();
  // Barycentrics of the hit (Embree's hit.u, hit.v): point = (1-u-v)·c0 + u·c1 + v·c2 with c the
  // element's corners in PatchMesh::corners() order.
  double u = 0, v = 0;
  bool hit() const { return element >= 0; }
};

// Linear motion of the vertices over a shutter interval (motion blur): vertex v sits at
// position(v) + open[v] at shutter time 0 and at position(v) + close[v] at time 1. Embree
// interpolates linearly between the two time steps, which is exact for a translation.
struct VertexMotion {
  std::vector<Eigen::Vector3d> open, close;  // one per PatchMesh vertex
};

// Owns the Embree device and a BVH over the PatchMesh's elements. Two Embree geometries: the
// opaque one-sided elements, and (only when the scene has any) the elements a ray may pass
// through, whose hits a filter function checks: the two sides of a two-sided surface (each a
// one-sided copy, addBackSides) are seen only from the side they face, and a cut-out is seen only
// where its coverage reaches the cutoff. The plain geometry pays nothing for the filter.
// The geometry is re-centred on its bounding box before conversion to float, so precision does
// not depend on where the scene sits in space; callers work in the scene's own coordinates.
// Thread-safe for queries once constructed. Embree errors become RuntimeFailure exceptions.
class RayCaster {
 public:
  // With `motion`, the BVH holds two time steps and queries take a shutter time in [0, 1].
  // Every element opaque and hit from both sides (a mesh without its scene).
  explicit RayCaster(const PatchMesh& mesh, const VertexMotion* motion = nullptr);
  // The mesh of `scene` (patch p = scene.polygons[p]): two-sided surfaces and cut-outs as the
  // scene's materials say. `scene` need not outlive the caster.
  RayCaster(const PatchMesh& mesh, const Scene& scene, const VertexMotion* motion = nullptr);
  // The same, without the elements flagged in `leftOut` (an edit's moved or added elements: what
  // the scene was, their old place aside), in the whole mesh's frame (centre, surface offset), so
  // that the whole scene's rays can be cast against it. Elements keep their mesh indices.
  RayCaster(const PatchMesh& mesh, const Scene& scene, const std::vector<char>& leftOut);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Closest element hit along origin + t·direction for t in [0, maxDistance] (lift the origin
  // off its surface first, see liftOff). `direction` need not
  // be normalised; distances are in units of |direction|. `time` in [0, 1] picks the moment of
  // the shutter interval for moving geometry (ignored without motion).
  RayHit closestHit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                    double maxDistance = std::numeric_limits<double>::infinity(),
                    double time = 0) const;
  // True when anything blocks origin + t·direction for t in [0, maxDistance]: pass a maxDistance
  // slightly short of the target so the target itself does not count.
  bool occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double maxDistance,
                double time = 0) const;

  // The batch form of closestHit for callers that make rays in bulk (form-factor rows): rays in
  // the caster's own frame (scene coordinates minus centre(), as Embree's floats), as separate
  // coordinate arrays, all cast with one intersect context and no per-ray conversion. Writes
  // each ray's closest element (-1: none) and its distance (infinite when none). With `nearest`,
  // ray k counts only hits beyond nearest[k] (the same ray, continued past what it hit first).
  void closestHits(int count, const float* const origin[3], const float* const direction[3],
                   int* element, float* distance, const float* nearest = nullptr) const;
  // The point the BVH is centred on: scene coordinates minus this are what Embree sees.
  const Eigen::Vector3d& centre() const { return centre_; }

  // Offset that lifts a ray origin off a surface: a small fraction of the scene's size, never a
  // fixed constant, so scenes in millimetres and in kilometres behave alike.
  double surfaceOffset() const { return offset_; }
  // Moves a point on an element's surface off it, to the side `towards` points to.
  Eigen::Vector3d liftOff(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                          const Eigen::Vector3d& towards) const {
    return point + (normal.dot(towards) >= 0 ? offset_ : -offset_) * normal;
  }

 private:
  // An element a ray may pass through, and why (primitive of the filtered geometry).
  struct FilteredElement {
    int element = -1;
    bool frontOnly = false;  // a side of a two-sided surface: hit only against its normal
    Eigen::Vector3f normal;  // the element's front normal
    int coverage = -1;       // index into coverages_, -1 when it has no holes
    std::array<Eigen::Vector2f, 3> uv;  // texture coordinates at its corners (with coverage)
  };
  static void filterHits(const RTCFilterFunctionNArguments* args);
  bool stopsRay(unsigned primitive, const Eigen::Vector3f& direction, float u, float v) const;
  void check(const char* what) const;
  RayCaster(const PatchMesh& mesh, const Scene& scene, const VertexMotion* motion,
            const std::vector<char>* leftOut);
  void build(const PatchMesh& mesh, const VertexMotion* motion, const std::vector<char>* leftOut);
  void addGeometry(const PatchMesh& mesh, const VertexMotion* motion, unsigned id,
                   const std::vector<int>& elements, bool filtered);
  int elementOf(unsigned geometry, unsigned primitive) const {
    return elementOf_[geometry][primitive];
  }
  void release();
  std::vector<FilteredElement> filtered_;
  std::vector<CoverageMap> coverages_;
  std::array<std::vector<int>, 2> elementOf_;  // per geometry: primitive → element
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  Eigen::Vector3d centre_;
  double offset_ = 0;
};

}  // namespace rad
