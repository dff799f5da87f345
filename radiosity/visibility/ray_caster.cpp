#include "radiosity/visibility/ray_caster.h"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"

namespace rad {
namespace {

// Embree reports errors through a callback on the calling thread; we keep the last message and
// throw from check() after each API call that can fail, since exceptions must not cross C code.
thread_local std::string t_lastError;

void onEmbreeError(void*, RTCError code, const char* message) {
  t_lastError = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                (message ? message : "(no message)");
}

}  // namespace

RayCaster::RayCaster(const PatchMesh& mesh, const VertexMotion* motion) {
  try {
    build(mesh, motion, nullptr);
  } catch (...) {
    release();  // the destructor does not run for a constructor that throws
    throw;
  }
}

RayCaster::RayCaster(const PatchMesh& mesh, const Scene& scene, const VertexMotion* motion)
    : RayCaster(mesh, scene, motion, nullptr) {}

RayCaster::RayCaster(const PatchMesh& mesh, const Scene& scene, const std::vector<char>& leftOut)
    : RayCaster(mesh, scene, nullptr, &leftOut) {}

RayCaster::RayCaster(const PatchMesh& mesh, const Scene& scene, const VertexMotion* motion,
                     const std::vector<char>* leftOut) {
  RAD_CHECK_EQ(mesh.patchCount(), scene.polygons.size());
  if (leftOut) RAD_CHECK_EQ(leftOut->size(), static_cast<size_t>(mesh.elementCount()));
  // Both sides of a two-sided surface are seen only from the side they face; a polygon whose
  // material is two-sided but has no back copy stays opaque from both sides.
  std::vector<bool> twoSided(scene.polygons.size(), false);
  for (std::size_t p = 0; p < scene.polygons.size(); ++p)
    if (scene.polygons[p].backSideOf >= 0)
      twoSided[p] = twoSided[static_cast<std::size_t>(scene.polygons[p].backSideOf)] = true;
  for (const Material& m : scene.materials) coverages_.emplace_back(m, scene.textures);
  bool holesWithoutUvs = false;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (leftOut && (*leftOut)[static_cast<size_t>(e)]) continue;
    const int material = mesh.material(e);
    bool holes = coverages_[static_cast<std::size_t>(material)].hasHoles();
    holesWithoutUvs |= holes && !mesh.hasUvs(e);
    holes = holes && mesh.hasUvs(e);
    if (!twoSided[static_cast<std::size_t>(mesh.patch(e))] && !holes) continue;
    FilteredElement f;
    f.element = e;
    f.frontOnly = twoSided[static_cast<std::size_t>(mesh.patch(e))];
    f.normal = mesh.normal(e).cast<float>();
    if (holes) {
      f.coverage = material;
      const auto uv = mesh.cornerUvs(e);
      for (int k = 0; k < 3; ++k) f.uv[k] = uv[k].cast<float>();
    }
    filtered_.push_back(f);
  }
  if (holesWithoutUvs && !leftOut)  // a caster leaving elements out stands beside the whole one
    logWarning("cut-outs are opaque where their polygons have no texture coordinates");
  try {
    build(mesh, motion, leftOut);
  } catch (...) {
    release();
    throw;
  }
}

void RayCaster::build(const PatchMesh& mesh, const VertexMotion* motion,
                      const std::vector<char>* leftOut) {
  if (motion) {  // one displacement per mesh vertex
    RAD_CHECK_EQ(motion->open.size(), mesh.vertexCount());
    RAD_CHECK_EQ(motion->close.size(), mesh.vertexCount());
  }
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw RuntimeFailure("cannot create the Embree device");
  rtcSetDeviceErrorFunction(device_, onEmbreeError, nullptr);

  centre_ = 0.5 * (mesh.boundsMin() + mesh.boundsMax());
  // Embree works in float; 1e-5 of the diagonal stays far above its intersection error for
  // re-centred coordinates yet below any gap a modeller would leave on purpose.
  offset_ = 1e-5 * std::max(mesh.boundsDiagonal(), std::numeric_limits<double>::min());

  scene_ = rtcNewScene(device_);
  // Robust traversal: no accuracy-reducing optimisations, so rays do not slip through the
  // shared edges of a closed mesh.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  std::vector<bool> isFiltered(static_cast<std::size_t>(mesh.elementCount()), false);
  std::vector<int> filtered, plain;
  for (const FilteredElement& f : filtered_) {
    isFiltered[static_cast<std::size_t>(f.element)] = true;
    filtered.push_back(f.element);
  }
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (!isFiltered[static_cast<std::size_t>(e)] &&
        !(leftOut && (*leftOut)[static_cast<size_t>(e)]))
      plain.push_back(e);
  if (!plain.empty()) addGeometry(mesh, motion, 0, plain, false);
  if (!filtered.empty()) addGeometry(mesh, motion, 1, filtered, true);
  rtcCommitScene(scene_);
  check("building the BVH");
}

void RayCaster::addGeometry(const PatchMesh& mesh, const VertexMotion* motion, unsigned id,
                            const std::vector<int>& elements, bool filtered) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  const TriMesh& m = mesh.mesh();
  const unsigned steps = motion ? 2 : 1;
  if (motion) rtcSetGeometryTimeStepCount(geometry, steps);
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), elements.size()));
  bool allocated = indices != nullptr;
  for (unsigned step = 0; step < steps && allocated; ++step) {
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), m.n_vertices()));
    allocated = vertices != nullptr;
    for (int v = 0; allocated && v < mesh.vertexCount(); ++v) {
      Eigen::Vector3d p = mesh.position(v) - centre_;
      if (motion) p += step == 0 ? motion->open[v] : motion->close[v];
      vertices[3 * v + 0] = static_cast<float>(p.x());
      vertices[3 * v + 1] = static_cast<float>(p.y());
      vertices[3 * v + 2] = static_cast<float>(p.z());
    }
  }
  if (!allocated) {
    rtcReleaseGeometry(geometry);
    check("allocating geometry buffers");
    throw RuntimeFailure("allocating geometry buffers failed");
  }
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto c = mesh.cornerVertices(elements[i]);
    for (int k = 0; k < 3; ++k) indices[3 * i + k] = static_cast<unsigned>(c[k]);
  }
  if (filtered) {
    rtcSetGeometryUserData(geometry, this);
    rtcSetGeometryIntersectFilterFunction(geometry, &RayCaster::filterHits);
    rtcSetGeometryOccludedFilterFunction(geometry, &RayCaster::filterHits);
  }
  elementOf_[id] = elements;
  rtcCommitGeometry(geometry);
  rtcAttachGeometryByID(scene_, geometry, id);
  rtcReleaseGeometry(geometry);
}

void RayCaster::filterHits(const RTCFilterFunctionNArguments* args) {
  const auto* self = static_cast<const RayCaster*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const Eigen::Vector3f direction(RTCRayN_dir_x(args->ray, args->N, i),
                                    RTCRayN_dir_y(args->ray, args->N, i),
                                    RTCRayN_dir_z(args->ray, args->N, i));
    if (!self->stopsRay(RTCHitN_primID(args->hit, args->N, i), direction,
                        RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)))
      args->valid[i] = 0;
  }
}

bool RayCaster::stopsRay(unsigned primitive, const Eigen::Vector3f& direction, float u,
                         float v) const {
  const FilteredElement& f = filtered_[primitive];
  if (f.frontOnly && !(f.normal.dot(direction) < 0)) return false;
  if (f.coverage < 0) return true;
  const Eigen::Vector2f uv = (1 - u - v) * f.uv[0] + u * f.uv[1] + v * f.uv[2];
  return coverages_[static_cast<std::size_t>(f.coverage)].stopsRayAt(uv.cast<double>());
}

void RayCaster::release() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
  scene_ = nullptr;
  device_ = nullptr;
}

RayCaster::~RayCaster() { release(); }

void RayCaster::check(const char* what) const {
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !t_lastError.empty()) {
    std::string message = t_lastError.empty() ? "unknown Embree error" : t_lastError;
    t_lastError.clear();
    throw RuntimeFailure(std::string(what) + ": " + message);
  }
}

namespace {
void fillRay(RTCRay& ray, const Eigen::Vector3d& o, const Eigen::Vector3d& d, double maxDistance,
             double time) {
  ray.org_x = static_cast<float>(o.x());
  ray.org_y = static_cast<float>(o.y());
  ray.org_z = static_cast<float>(o.z());
  ray.dir_x = static_cast<float>(d.x());
  ray.dir_y = static_cast<float>(d.y());
  ray.dir_z = static_cast<float>(d.z());
  ray.tnear = 0.0f;
  ray.tfar =
      maxDistance < 3e38 ? static_cast<float>(maxDistance) : std::numeric_limits<float>::infinity();
  ray.time = static_cast<float>(time);
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
}
}  // namespace

RayHit RayCaster::closestHit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                             double maxDistance, double time) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  fillRay(rayHit.ray, origin - centre_, direction, maxDistance, time);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayHit);
  RayHit result;
  if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
    result.element = elementOf(rayHit.hit.geomID, rayHit.hit.primID);
    result.distance = rayHit.ray.tfar;
    result.u = rayHit.hit.u;
    result.v = rayHit.hit.v;
  }
  return result;
}

void RayCaster::closestHits(int count, const float* const origin[3],
                            const float* const direction[3], int* element, float* distance,
                            const float* nearest) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray.time = 0.0f;
  rayHit.ray.mask = 0xFFFFFFFFu;
  rayHit.ray.id = 0;
  rayHit.ray.flags = 0;
  for (int k = 0; k < count; ++k) {
    rayHit.ray.org_x = origin[0][k];
    rayHit.ray.org_y = origin[1][k];
    rayHit.ray.org_z = origin[2][k];
    rayHit.ray.dir_x = direction[0][k];
    rayHit.ray.dir_y = direction[1][k];
    rayHit.ray.dir_z = direction[2][k];
    rayHit.ray.tnear = nearest ? nearest[k] : 0.0f;
    rayHit.ray.tfar = std::numeric_limits<float>::infinity();
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rayHit);
    const bool hit = rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    element[k] = hit ? elementOf(rayHit.hit.geomID, rayHit.hit.primID) : -1;
    distance[k] = rayHit.ray.tfar;  // stays infinite on a miss
  }
}

bool RayCaster::occluded(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                         double maxDistance, double time) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  fillRay(ray, origin - centre_, direction, maxDistance, time);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf when the ray is blocked
}

}  // namespace rad
