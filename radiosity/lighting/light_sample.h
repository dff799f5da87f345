#pragma once

#include <Eigen/Core>
#include <limits>

#include "radiosity/core/rgb.h"
#include "radiosity/scene/lights.h"

namespace rad {

// The lights of scene/lights.h as every estimator samples them: the solve's first shot
// (pipeline/direct_light_stage), the renders' next-event estimation (render/scene_lights), the
// bake's texels and the probes (render/light_probes) are loops over sampleLight, each casting its
// own shadow ray (the caster is theirs: the solve's, a render's moving scene). Adding a light type
// means one more case here and in light_shapes.h, nowhere else.
//
// Delta lights (isDeltaLight: point, spot, a sun of angular diameter 0) come from one direction,
// which no scattered ray can hit: a sample is that direction, exactly, with pdf 1. The others
// (a sun's disc, the skies, an environment) are sampled by a density over directions that
// lightPdf gives for any direction, so a cosine-sampled ray that leaves the scene and finds them
// (radianceAlong) can be weighed against the light's own samples by multiple importance sampling.

// Whether `light` is a delta light: point, spot, or a directional light of angular diameter 0.
bool isDeltaLight(const Light& light);

// One sample of a light's light at a point.
struct LightSample {
  Eigen::Vector3d direction{0, 0, 1};  // unit, from the lit point towards the light
  // How far the light is along `direction`: a shadow ray tests this far; infinity for lights at
  // infinity (the sun, the skies, an environment).
  double distance = std::numeric_limits<double>::infinity();
  // Area lights: the radiance L along `direction` (W·m⁻²·sr⁻¹). Delta lights: E⊥, the irradiance
  // on a surface facing the light (W·m⁻²; a point or spot: I × falloff / r²), which is what a
  // probe or a directional lightmap adds along `direction`.
  Rgb radiance;
  double pdf = 0;       // area lights: the density in solid angle of `direction`; delta: 1
  bool delta = false;   // isDeltaLight
  double cosTheta = 0;  // the normal's cosine with `direction`
  // The sample's estimate of the irradiance on the surface, unshadowed: delta E⊥ cosθ; area
  // L cosθ / pdf. 0 when the sample is behind the surface, outside a spot's cone or of no light.
  Rgb irradiance;
  bool found() const { return !irradiance.isZero(); }
};

// A sample of `light` seen from a point x with unit normal n (only its front receives), from a
// point (u1, u2) of the unit square, stratified where the caller stratifies them. Point: towards
// the light; spot: the same, times the spot's falloff (light_shapes.h); a hard sun: its centre;
// a sun's disc: uniform in solid angle over it (density 1/Ω); an environment or a CIE clear sky:
// by the map's luminance (EnvironmentMap::pdf); the other skies: cosine-weighted about n (density
// cosθ/π), the ground below the horizon black.
LightSample sampleLight(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                        double u1, double u2);

// The density (solid angle) with which sampleLight draws the unit direction `w` at a point of
// unit normal n: 0 for delta lights and for directions the light cannot send.
double lightPdf(const Light& light, const Eigen::Vector3d& n, const Eigen::Vector3d& w);

// What a ray leaving the scene in the unit direction `w` sees of `light`: the sun's disc, the
// sky above its horizon, the environment all round; nothing of a delta light.
Rgb radianceAlong(const Light& light, const Eigen::Vector3d& w);

// The irradiance at x (unit normal n) from `light`, nothing in the way, in closed form where there
// is one: a point or spot I cosθ falloff / r², a sun E cosθ at its disc's centre, a sky or
// environment over the part of it above the plane (skyIrradiance).
Rgb unshadowedIrradiance(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n);

}  // namespace rad
