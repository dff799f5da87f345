#pragma once

#include <Eigen/Core>

#include "radiosity/core/rgb.h"
#include "radiosity/scene/lights.h"

namespace rad {

// How the lights of lights.h spread their light over directions: the one definition that the
// radiosity first shot (pipeline/direct_light_stage) and the camera renders (render/scene_lights)
// both use, so every method sees the same spot, sun and sky.

// The spot's falloff: 0 outside the outer cone, 1 inside the inner one, smoothstep in cos between
// (a hard edge when the cones are equal). `cosAngle`: cosine between the axis and the direction
// from the light to the lit point.
double spotFalloff(const Light& light, double cosAngle);

// The sun's disc, for a directional light with an angular diameter: a cone of half-angle h around
// the direction towards the sun, of uniform radiance L = E / (π sin²h), so that a surface facing
// the sun receives ∫ L cosα dω = L π sin²h = E (its `irradiance`).
double sunCosHalfAngle(const Light& light);  // cos h; 1 for a hard sun
double sunSolidAngle(const Light& light);    // 2π (1 − cos h); 0 for a hard sun
Rgb sunRadiance(const Light& light);         // L = E / (π sin²h)
// A direction towards the sun uniform in solid angle over its disc (density 1/sunSolidAngle)
// from a point (u1, u2) of the unit square; the disc's centre for a hard sun.
Eigen::Vector3d sunDirection(const Light& light, double u1, double u2);
// Whether the unit `direction` (from a surface towards the sky) lies within the sun's disc.
bool insideSunDisc(const Light& light, const Eigen::Vector3d& direction);

// The CIE standard clear sky (CIE S 011/E:2003 type 12; Kittler 1967) relative to its zenith:
//   L(θ, γ) / L_z = f(γ) φ(θ) / (f(θs) φ(0)),  f(x) = 0.91 + 10 e^(−3x) + 0.45 cos²x,
//   φ(θ) = 1 − e^(−0.32 / cos θ),
// θ the zenith angle of the unit `direction`, γ its angle to the sun (unit `toSun`), θs the sun's
// zenith angle; 0 at and below the horizon of `up`.
double cieClearSkyRatio(const Eigen::Vector3d& direction, const Eigen::Vector3d& toSun,
                        const Eigen::Vector3d& up);

// The radiance of a sky or an environment along the unit `direction` (from a surface towards
// it): the sky's model above the horizon of `up` (lights.h), black ground below; the environment
// image's texel (environment_map.h), the ground half too. The one definition both the solve and
// the renders evaluate; those with a `map` (environment, clear sky) are sampled by it
// (EnvironmentMap::sample, density EnvironmentMap::pdf), the others cosine-weighted.
Rgb skyRadiance(const Light& light, const Eigen::Vector3d& direction);
// The irradiance from the whole sky, unshadowed, on a plane of unit normal `n` at angle α to `up`
// (integrated over the lune above both the horizon and the plane): uniform πL (1 + cos α)/2;
// CIE overcast L_z [π (1 + cos α)/6 + 4/9 (sin α + (π − α) cos α)], 7πL_z/9 facing up; the clear
// sky and the environment from their map's irradiance table (EnvironmentMap::irradiance).
Rgb skyIrradiance(const Light& light, const Eigen::Vector3d& n);

}  // namespace rad
