#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/render/emitter_sampler.h"
#include "radiosity/render/scene_lights.h"
#include "radiosity/render/scene_motion.h"
#include "radiosity/scene/scene.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Rays one pixel (or one path) cast, summed into the render's statistics.
struct RayCounts {
  uint64_t camera = 0;          // primary rays
  uint64_t closest = 0;         // closest-hit rays after the first (gather, specular, path bounces)
  uint64_t shadow = 0;          // occlusion rays
  uint64_t gathersSkipped = 0;  // diffuse first hits that needed no gather (black emitters)
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera;
    closest += o.closest;
    shadow += o.shadow;
    gathersSkipped += o.gathersSkipped;
    return *this;
  }
  uint64_t total() const { return camera + closest + shadow; }
};

struct SurfaceHit {
  int element = -1;
  Eigen::Vector3d position, normal;  // normal: the element's front (geometric) normal
  double u = 0, v = 0, distance = 0;
  bool front = false;  // the ray arrived on the front (counter-clockwise) side
  const Material* material = nullptr;
  // The diffuse reflectance at this point: Kd × the colour map's bilinear texel (Kd alone when
  // untextured). What every render method scatters with, so texture detail shows.
  Rgb diffuse;
  bool hit() const { return element >= 0; }
};

// What the eye and path passes see of a meshed scene: materials per element, ray queries, and
// the emitters to sample. Holds references; the scene, mesh and caster must outlive it.
class RenderScene {
 public:
  // `motion` (optional, for motion blur): the moving elements; the caster must have been built
  // with motion->vertices. Queries then take a shutter time in [0, 1].
  RenderScene(const Scene& scene, const PatchMesh& mesh, const RayCaster& caster,
              const SceneMotion* motion = nullptr);

  SurfaceHit intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                       double time = 0) const;
  // True when the segment from `from` (already lifted off its surface) to `to` (a point on a
  // surface) is blocked. Stops short of `to` by the caster's surface offset.
  bool occluded(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double time = 0) const;
  // True when the ray from `from` (already lifted off its surface) along the unit `direction`
  // hits anything: a light at infinity (the sun, the sky) is blocked that way.
  bool occludedAlong(const Eigen::Vector3d& from, const Eigen::Vector3d& direction,
                     double time = 0) const;
  // A ray origin on `hit` lifted off the surface to the side `direction` leaves towards.
  Eigen::Vector3d spawn(const SurfaceHit& hit, const Eigen::Vector3d& direction) const {
    return caster_.liftOff(hit.position, hit.normal, direction);
  }

  const Scene& scene() const { return scene_; }
  const PatchMesh& mesh() const { return mesh_; }
  const Material& material(int element) const { return scene_.materials[mesh_.material(element)]; }
  const EmitterSampler& emitters() const { return emitters_; }
  // The point, spot, directional and sky lights (besides the emissive polygons).
  const SceneLights& lights() const { return lights_; }
  bool hasSpecular() const { return hasSpecular_; }
  bool hasMotion() const { return motion_ != nullptr; }
  const RayCaster& caster() const { return caster_; }

 private:
  const Scene& scene_;
  const PatchMesh& mesh_;
  const RayCaster& caster_;
  const SceneMotion* motion_;
  EmitterSampler emitters_;
  SceneLights lights_;
  std::vector<std::array<Eigen::Vector3d, 3>> corners_;
  std::vector<Eigen::Vector3d> normals_;
  bool hasSpecular_ = false;
};

}  // namespace rad
