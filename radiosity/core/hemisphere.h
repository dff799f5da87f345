#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace rad {

// The cosine-weighted hemisphere and the frame about a normal: shared by the form factors'
// rows and the lights' samples (lighting/), which draw the same directions from the same numbers.

// Cosine-weighted direction about +z: theta = acos(sqrt(u1)), phi = 2 pi u2. The density is
// cos(theta)/pi, so the fraction of such rays that reach a surface estimates the form factor.
inline Eigen::Vector3d cosineWeightedDirection(double u1, double u2) {
  const double cosTheta = std::sqrt(u1);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - u1));
  const double phi = 2.0 * M_PI * u2;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Orthonormal tangent frame (t, b, n) for a unit normal n, without branches on near-axis
// normals (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
struct Frame {
  Eigen::Vector3d tangent, bitangent, normal;
  explicit Frame(const Eigen::Vector3d& n) : normal(n) {
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double b = n.x() * n.y() * a;
    tangent = {1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x()};
    bitangent = {b, sign + n.y() * n.y() * a, -n.y()};
  }
  Eigen::Vector3d toWorld(const Eigen::Vector3d& local) const {
    return local.x() * tangent + local.y() * bitangent + local.z() * normal;
  }
};

}  // namespace rad
