#pragma once

#include <Eigen/Core>
#include <cmath>

#include "radiosity/render/scattering.h"
#include "radiosity/scene/material.h"

namespace rad {

// Unit t, s with (t, s, n) orthonormal: the branch-free basis of Duff et al. 2017, as in
// cosineDirection.
inline void orthonormalBasis(const Eigen::Vector3d& n, Eigen::Vector3d& t, Eigen::Vector3d& s) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z()), b = n.x() * n.y() * a;
  t = Eigen::Vector3d(1 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  s = Eigen::Vector3d(b, sign + n.y() * n.y() * a, -n.y());
}

// The normalised (energy-conserving) Phong lobe of an MTL illum 2 material with Ks and Ns:
//   f_g(ω_i, ω_o) = Ks · (n+2)/(2π) · cos^n α,  α = angle(ω_i, mirror of ω_o).
// (n+2)/(2π) makes ∫ f_g cosθ dω = Ks at normal incidence and less elsewhere (Lafortune and
// Willems 1994), so Kd + Ks ≤ 1 conserves energy.
struct GlossyLobe {
  Rgb ks;
  double exponent = 0;

  static bool applies(const Material& m) {
    return m.kind == SurfaceKind::Diffuse && m.illum == 2 && m.specular.maxComponent() > 0 &&
           m.shininess > 0;
  }
  explicit GlossyLobe(const Material& m) : ks(m.specular), exponent(m.shininess) {}

  // cos^n α for a direction `w` and the mirror direction `mirror` (both unit).
  double lobe(const Eigen::Vector3d& w, const Eigen::Vector3d& mirror) const {
    const double c = w.dot(mirror);
    return c > 0 ? std::pow(c, exponent) : 0.0;
  }
  Rgb brdf(const Eigen::Vector3d& w, const Eigen::Vector3d& mirror) const {
    return ks * ((exponent + 2) / (2 * M_PI) * lobe(w, mirror));
  }
  // Solid-angle density of sample().
  double pdf(const Eigen::Vector3d& w, const Eigen::Vector3d& mirror) const {
    return (exponent + 1) / (2 * M_PI) * lobe(w, mirror);
  }
  // A direction around `mirror` with density pdf(): cos α = u1^(1/(n+1)).
  Eigen::Vector3d sample(const Eigen::Vector3d& mirror, double u1, double u2) const {
    const double cosA = std::pow(u1, 1.0 / (exponent + 1));
    const double sinA = std::sqrt(std::max(0.0, 1 - cosA * cosA)), phi = 2 * M_PI * u2;
    Eigen::Vector3d t, s;
    orthonormalBasis(mirror, t, s);
    return (sinA * std::cos(phi) * t + sinA * std::sin(phi) * s + cosA * mirror).normalized();
  }
};

}  // namespace rad
