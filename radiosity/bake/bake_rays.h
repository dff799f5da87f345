#pragma once

#include <memory>

#include "radiosity/pipeline/solution.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The solved scene's BVH and the renders' view of it, each built on first use: a bake casts rays
// only for the buried parts of elements when the solve did not keep them, for the per-texel
// gather and for the directional pages.
class BakeRays {
 public:
  explicit BakeRays(const Solution& solution) : solution_(solution) {}

  const RayCaster& caster();
  const RenderScene& view();

 private:
  const Solution& solution_;
  std::unique_ptr<const RayCaster> caster_;
  std::unique_ptr<const RenderScene> view_;
};

}  // namespace rad
