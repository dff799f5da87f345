#pragma once

#include <embree3/rtcore.h>

#include <Eigen/Core>
#include <array>
#include <vector>

namespace rad {

// A small BVH over a set of triangles, asked only whether a ray meets any of them: `update`'s
// test of which form-factor rays pass through what moved (the old and new places of the edited
// geometry). Triangles are stored as RayCaster stores its own, in float relative to the same
// `centre`, so rays in that caster's frame (its closestHits arrays) are tested as they are cast.
// Every triangle is hit from both sides. Thread-safe for queries once constructed.
class TriangleSetCaster {
 public:
  // `sceneSize` (the diagonal of everything rays start from) sizes the slab test's margin: its
  // rounding grows with the origins' distance from `centre`, not with the triangles'.
  TriangleSetCaster(const std::vector<std::array<Eigen::Vector3d, 3>>& triangles,
                    const Eigen::Vector3d& centre, double sceneSize);
  ~TriangleSetCaster();
  TriangleSetCaster(const TriangleSetCaster&) = delete;
  TriangleSetCaster& operator=(const TriangleSetCaster&) = delete;

  bool empty() const { return scene_ == nullptr; }
  // The triangles' bounding box, in scene coordinates (empty() when there are none).
  const Eigen::Vector3d& boundsMin() const { return lo_; }
  const Eigen::Vector3d& boundsMax() const { return hi_; }
  // For each ray (origins and directions in the caster's frame, as RayCaster::closestHits takes
  // them), the distance ahead of its origin to the first triangle it meets, in units of its
  // direction's length; infinite when it meets none. `triangle`, if given: that triangle's index
  // (-1 for none).
  void distances(int count, const float* const origin[3], const float* const direction[3],
                 float* distance, int* triangle = nullptr) const;
  // Whether `direction` meets triangle t's front side (against its right-hand-rule normal, as
  // PatchMesh::normal, in float as the form-factor rays test an element's).
  bool meetsFront(int t, const float direction[3]) const {
    const float* n = &normals_[3 * static_cast<size_t>(t)];
    return n[0] * direction[0] + n[1] * direction[1] + n[2] * direction[2] < 0;
  }

 private:
  void release();
  // Whether the ray (caster frame) surely misses the triangles' widened box.
  bool missesBox(float ox, float oy, float oz, float dx, float dy, float dz) const;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  Eigen::Vector3d lo_{0, 0, 0}, hi_{0, 0, 0};
  float boxLo_[3] = {0, 0, 0}, boxHi_[3] = {0, 0, 0};  // caster frame, widened
  std::vector<float> normals_;                         // 3 per triangle
};

}  // namespace rad
