#pragma once

#include <Eigen/Core>
#include <vector>

#include "radiosity/core/fresnel.h"
#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// How an element scatters specularly, for extended form factors. Diffuse elements end a path.
struct SpecularSurface {
  enum class Kind { Diffuse, Mirror, Dielectric };
  Kind kind = Kind::Diffuse;
  Rgb reflectance = Rgb::all(1);    // mirror: Ks
  Rgb transmittance = Rgb::all(1);  // dielectric: Tf, applied on entering the medium
  double ior = 1.5;                 // dielectric: Ni
};

// Where a ray ends after mirrors and glass: the first diffuse element whose front it reaches
// (element −1 if it escapes, hits a back face, ends in Russian roulette or bounces
// kSpecularBounceLimit times), and the specular reflectance and transmittance it picked up on the
// way (divided by the roulette's survival probabilities past kSpecularRouletteAfter bounces,
// never above 1: survivesRouletteWithinOne).
struct SpecularPathEnd {
  int element = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // where it reached `element`
  Rgb weight = Rgb::all(1);
  int specularBounces = 0;
};

// Follows origin + t·direction (unit direction) from the surface of element `from`. Mirrors
// reflect (one-sided, like every surface); glass reflects or refracts with probability given by
// the Fresnel reflectance (unpolarised, exact dielectric formula), so the weight carries only the
// colour filters and the estimate stays unbiased. `rng` supplies the Fresnel choices.
SpecularPathEnd traceThroughSpecular(const RayCaster& rays,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<SpecularSurface>& surfaces,
                                     Eigen::Vector3d origin, Eigen::Vector3d direction, int from,
                                     Rng& rng, int* raysCast);

}  // namespace rad
