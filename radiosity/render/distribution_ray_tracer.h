#pragma once

#include "radiosity/render/integrator.h"

namespace rad {

struct DistributionOptions {
  int maxDepth = 16;  // mirror, glass and glossy interactions along one path
};

// Distribution ray tracing (Cook, Porter, Carpenter 1984): Whitted's recursion with every
// integral that it point-samples replaced by a Monte Carlo sample, one per camera sample —
//  - soft shadows: a point on an area emitter (chosen by power, as the path tracer does) behind
//    one shadow ray, so penumbrae come out right, not the point lights of `whitted`;
//  - glossy reflection: illum 2 materials with Ks > 0 and Ns > 0 get a normalised Phong lobe
//    f_g = Ks·(n+2)/(2π)·cos^n α (α between the outgoing direction and the mirror direction),
//    energy-conserving for Kd + Ks ≤ 1; one direction sampled from cos^n α (pdf
//    (n+1)/(2π)·cos^n α) continues the path, with multiple importance sampling (power
//    heuristic) against the emitter sample so that neither small lights nor sharp lobes are
//    noisy;
//  - glass chooses Fresnel reflection or refraction at random (scatterSpecular);
//  - depth of field comes from the thin-lens camera (lens_radius, focus_distance), sampled by
//    the image renderer; motion blur from a shutter time τ drawn uniformly in [0, 1) per camera
//    sample and carried by every ray of that sample through the motion-blur BVH.
// The point, spot and directional lights and the sky light every diffuse surface by one shadow
// ray each (the glossy lobe too for the delta lights); rays that leave the scene see the sky.
// Diffuse surfaces end the path (no diffuse interreflection): paths `L D? S* E`, where S
// includes the glossy lobes.
class DistributionRayTracer : public Integrator {
 public:
  explicit DistributionRayTracer(const RenderScene& scene, DistributionOptions options = {});
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override;
  std::string name() const override { return "distribution ray tracing"; }

 private:
  const RenderScene& scene_;
  DistributionOptions options_;
};

}  // namespace rad
