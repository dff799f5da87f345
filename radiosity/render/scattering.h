#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "radiosity/core/fresnel.h"
#include "radiosity/core/rgb.h"
#include "radiosity/core/russian_roulette.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/material.h"

namespace rad {

// Cosine-weighted direction around unit `n` (pdf cosθ/π): a uniform disc point (r = √u1)
// lifted to the hemisphere (Malley), in a branch-free orthonormal basis (Duff et al. 2017).
inline Eigen::Vector3d cosineDirection(const Eigen::Vector3d& n, double u1, double u2) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z()), b = n.x() * n.y() * a;
  const Eigen::Vector3d t(1 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  const Eigen::Vector3d s(b, sign + n.y() * n.y() * a, -n.y());
  const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
  const double z = std::sqrt(std::max(0.0, 1 - u1));
  return (r * std::cos(phi) * t + r * std::sin(phi) * s + z * n).normalized();
}

inline Eigen::Vector3d reflect(const Eigen::Vector3d& d, const Eigen::Vector3d& n) {
  return d - 2 * d.dot(n) * n;
}

// What a path carries: radiance (eye paths) or importance (light paths, which bidirectional
// methods walk from the emitters). They scale differently only where glass refracts.
enum class Transport { Radiance, Importance };

// One step along a specular chain: the ray leaving a mirror or glass hit and the factor the
// path's throughput takes. `u` chooses between Fresnel reflection and refraction at glass.
struct SpecularStep {
  bool alive = false;  // false: absorbed (the back of a mirror)
  Eigen::Vector3d origin, direction;
  Rgb weight;
};

inline SpecularStep scatterSpecular(const RenderScene& scene, const SurfaceHit& hit,
                                    const Eigen::Vector3d& direction, double u,
                                    Transport transport = Transport::Radiance) {
  SpecularStep step;
  const Material& m = *hit.material;
  if (m.kind == SurfaceKind::Mirror) {
    if (!hit.front) return step;  // one-sided like every other surface
    step.direction = reflect(direction, hit.normal);
    step.weight = m.specular;
  } else {
    // Dielectric: the front side is outside (index 1), the back side inside (index Ni).
    const bool entering = hit.front;
    const Eigen::Vector3d n = entering ? hit.normal : Eigen::Vector3d(-hit.normal);
    const double etaI = entering ? 1.0 : m.ior, etaT = entering ? m.ior : 1.0;
    const double cosI = -direction.dot(n);
    const double f = fresnelDielectric(cosI, etaI, etaT);
    if (u < f) {  // reflect with probability F: the weight F/F is 1
      step.direction = reflect(direction, n);
      step.weight = Rgb::all(1.0);
    } else {  // refract with probability 1−F: weight Tf·(1−F)/(1−F), radiance scaled by (ηi/ηt)²
      const double eta = etaI / etaT;
      const double cosT = std::sqrt(std::max(0.0, 1 - eta * eta * (1 - cosI * cosI)));
      step.direction = (eta * direction + (eta * cosI - cosT) * n).normalized();
      step.weight = m.transmittance * (eta * eta);
    }
  }
  step.origin = scene.spawn(hit, step.direction);
  step.alive = step.weight.maxComponent() > 0;
  if (step.alive && transport == Transport::Importance &&
      step.direction.dot(hit.normal) * direction.dot(hit.normal) > 0) {
    // Refracted: the weight above scales radiance by (ηi/ηt)² for an eye ray going from ηi into
    // ηt; light crossing the same way scales by (ηt/ηi)², so full paths agree.
    const double eta = hit.front ? m.ior : 1.0 / m.ior;  // ηt/ηi along the light's travel
    step.weight *= eta * eta * eta * eta;
  }
  return step;
}

// The continuation of a path at a mirror or glass hit, as every path-building method takes it:
// the Fresnel choice is drawn from uniform() at glass only (a mirror draws no random number),
// `origin` and `direction` move onto the scattered ray and `throughput` takes its weight. Returns
// false, changing nothing, where the path ends there (the back of a mirror, a zero weight).
template <class Uniform>
bool continueSpecular(const RenderScene& scene, const SurfaceHit& hit, Eigen::Vector3d& origin,
                      Eigen::Vector3d& direction, Rgb& throughput, Uniform&& uniform,
                      Transport transport = Transport::Radiance) {
  const double u = hit.material->kind == SurfaceKind::Dielectric ? uniform() : 0.0;
  const SpecularStep step = scatterSpecular(scene, hit, direction, u, transport);
  if (!step.alive) return false;
  throughput = throughput * step.weight;
  origin = step.origin;
  direction = step.direction;
  return true;
}

}  // namespace rad
