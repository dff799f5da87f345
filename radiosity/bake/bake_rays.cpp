#include "radiosity/bake/bake_rays.h"

namespace rad {

const RayCaster& BakeRays::caster() {
  if (!caster_) caster_ = std::make_unique<const RayCaster>(*solution_.mesh, solution_.scene);
  return *caster_;
}

const RenderScene& BakeRays::view() {
  if (!view_)
    view_ = std::make_unique<const RenderScene>(solution_.scene, *solution_.mesh, caster());
  return *view_;
}

}  // namespace rad
