#include "radiosity/render/diffuse_eye_hit.h"

#include "radiosity/core/russian_roulette.h"
#include "radiosity/render/scattering.h"
#include "radiosity/render/scene_lights.h"

namespace rad {

DiffuseEyeHit traceToDiffuse(const RenderScene& scene, Eigen::Vector3d origin,
                             Eigen::Vector3d direction, Sampler& sampler, RayCounts& counts) {
  DiffuseEyeHit out;
  Rgb weight = Rgb::all(1.0);
  for (int depth = 0;; ++depth) {
    const SurfaceHit hit = scene.intersect(origin, direction);
    ++(depth == 0 ? counts.camera : counts.closest);
    if (!hit.hit()) {
      out.radiance = weight * scene.lights().escapedRadiance(direction);  // the sky
      return out;
    }
    if (hit.material->isSpecular()) {
      if (depth >= kSpecularBounceLimit ||
          (depth >= kSpecularRouletteAfter && !survivesRouletteWithinOne(weight, sampler.get1D())))
        return out;
      if (!continueSpecular(scene, hit, origin, direction, weight, [&] { return sampler.get1D(); }))
        return out;
      continue;
    }
    if (!hit.front) return out;
    out.reached = true;
    out.hit = hit;
    out.weight = weight;
    return out;
  }
}

}  // namespace rad
