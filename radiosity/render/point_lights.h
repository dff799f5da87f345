#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/render_scene.h"

namespace rad {

// An emitting polygon shrunk to a point at its centre, as the classic local model and Whitted's
// ray tracer see lights. Seen from far away a one-sided Lambertian emitter of radiance Le and
// area A has intensity I(θ) = Le·A·cosθ (W·sr⁻¹ per channel, θ from its normal), so a surface
// at distance r whose normal makes angle θs with the direction to the light receives
//   E = Le·A·cosθ·cosθs / r².
// That is the far-field limit of the exact form factor: it overestimates near a large light.
struct PointLight {
  Eigen::Vector3d position, normal;  // area-weighted centroid and mean front normal
  double area = 0;
  Rgb radiance;  // Le (Ke of the material)
  int patch = -1;

  // Irradiance at `point` with unit `surfaceNormal`, ignoring anything in between (zero when
  // either side faces away).
  Rgb irradiance(const Eigen::Vector3d& point, const Eigen::Vector3d& surfaceNormal) const {
    const Eigen::Vector3d w = position - point;
    const double r2 = w.squaredNorm();
    if (!(r2 > 0)) return {};
    const double r = std::sqrt(r2);
    const double cosS = surfaceNormal.dot(w) / r, cosL = -normal.dot(w) / r;
    if (cosS <= 0 || cosL <= 0) return {};
    return radiance * (area * cosL * cosS / r2);
  }
};

// One point light per emitting patch (input polygon) of the scene.
std::vector<PointLight> emitterPointLights(const RenderScene& scene);

}  // namespace rad
