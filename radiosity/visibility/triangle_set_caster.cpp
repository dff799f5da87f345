#include "radiosity/visibility/triangle_set_caster.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <string>

#include "radiosity/core/errors.h"

namespace rad {

TriangleSetCaster::TriangleSetCaster(const std::vector<std::array<Eigen::Vector3d, 3>>& triangles,
                                     const Eigen::Vector3d& centre, double sceneSize) {
  if (triangles.empty()) return;  // meets nothing
  lo_ = hi_ = triangles[0][0];
  for (const auto& t : triangles)
    for (const Eigen::Vector3d& p : t) {
      lo_ = lo_.cwiseMin(p);
      hi_ = hi_.cwiseMax(p);
    }
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw RuntimeFailure("cannot create the Embree device");
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), triangles.size()));
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               3 * triangles.size()));
  if (!indices || !vertices) {
    rtcReleaseGeometry(geometry);
    release();
    throw RuntimeFailure("allocating the moved geometry's buffers failed");
  }
  normals_.resize(3 * triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t];
    const Eigen::Vector3d normal = (c[1] - c[0]).cross(c[2] - c[0]).normalized();
    for (int d = 0; d < 3; ++d) normals_[3 * t + d] = static_cast<float>(normal[d]);
  }
  for (size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = triangles[t][k] - centre;  // as RayCaster converts its vertices
      for (int d = 0; d < 3; ++d) vertices[9 * t + 3 * k + d] = static_cast<float>(p[d]);
      indices[3 * t + k] = static_cast<unsigned>(3 * t + k);
    }
  // The float box of those vertices, widened far beyond the slab test's rounding, so that a ray
  // it rejects cannot meet a triangle: a few float ulps of the coordinates involved, the box's and
  // the ray origins' (anywhere in the scene; a 1 mm triangle seen from 50 m away lost rays to the
  // rounding of (lo − o) / d without the last term).
  const Eigen::Vector3d lo = lo_ - centre, hi = hi_ - centre;
  const double margin = 1e-4 * std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff()) +
                        1e-4 * (hi - lo).maxCoeff() + 1e-5 * std::abs(sceneSize);
  for (int d = 0; d < 3; ++d) {
    boxLo_[d] = static_cast<float>(lo[d] - margin);
    boxHi_[d] = static_cast<float>(hi[d] + margin);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    release();
    throw RuntimeFailure("building the BVH of the moved geometry failed");
  }
}

TriangleSetCaster::~TriangleSetCaster() { release(); }

bool TriangleSetCaster::missesBox(float ox, float oy, float oz, float dx, float dy,
                                  float dz) const {
  const float o[3] = {ox, oy, oz}, d[3] = {dx, dy, dz};
  float enter = 0, leave = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0) {
      if (o[a] < boxLo_[a] || o[a] > boxHi_[a]) return true;
      continue;
    }
    const float t0 = (boxLo_[a] - o[a]) / d[a], t1 = (boxHi_[a] - o[a]) / d[a];
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
  }
  return leave < enter;
}

void TriangleSetCaster::release() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
  scene_ = nullptr;
  device_ = nullptr;
}

void TriangleSetCaster::distances(int count, const float* const origin[3],
                                  const float* const direction[3], float* distance,
                                  int* triangle) const {
  if (triangle)
    for (int k = 0; k < count; ++k) triangle[k] = -1;
  if (!scene_) {
    for (int k = 0; k < count; ++k) distance[k] = std::numeric_limits<float>::infinity();
    return;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray.time = 0.0f;
  rayHit.ray.mask = 0xFFFFFFFFu;
  rayHit.ray.id = 0;
  rayHit.ray.flags = 0;
  for (int k = 0; k < count; ++k) {
    // Most rays pass far from the (small) set: a slab test against its box spares them Embree's
    // call, which costs several times more even for a ray that misses its root.
    if (missesBox(origin[0][k], origin[1][k], origin[2][k], direction[0][k], direction[1][k],
                  direction[2][k])) {
      distance[k] = std::numeric_limits<float>::infinity();
      continue;
    }
    rayHit.ray.org_x = origin[0][k];
    rayHit.ray.org_y = origin[1][k];
    rayHit.ray.org_z = origin[2][k];
    rayHit.ray.dir_x = direction[0][k];
    rayHit.ray.dir_y = direction[1][k];
    rayHit.ray.dir_z = direction[2][k];
    rayHit.ray.tnear = 0.0f;
    rayHit.ray.tfar = std::numeric_limits<float>::infinity();
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rayHit);
    const bool met = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    distance[k] = met ? rayHit.ray.tfar : std::numeric_limits<float>::infinity();
    if (triangle && met) triangle[k] = static_cast<int>(rayHit.hit.primID);
  }
}

}  // namespace rad
