#pragma once

#include <Eigen/Core>
#include <array>

namespace rad {

// The points where an element receives light: the degree-2 Gauss points of the triangle
// (barycentric 2/3, 1/6, 1/6), interior, so never on a shared edge; point k lies near corner k.
// With one receiver point all three are the centroid. The analytic form factors and the direct
// light of point, spot, directional and sky lights use the same points.
// Barycentric weights (of corners 0, 1, 2) of receiver point k of three.
inline Eigen::Vector3d receiverWeights(int k) {
  Eigen::Vector3d w = Eigen::Vector3d::Constant(1.0 / 6);
  w[k] = 2.0 / 3;
  return w;
}

inline std::array<Eigen::Vector3d, 3> receiverPoints(const std::array<Eigen::Vector3d, 3>& c,
                                                     int count = 3) {
  std::array<Eigen::Vector3d, 3> points;
  for (int k = 0; k < 3; ++k)
    points[k] = count == 1 ? Eigen::Vector3d((c[0] + c[1] + c[2]) / 3.0)
                           : Eigen::Vector3d((4.0 * c[k] + c[(k + 1) % 3] + c[(k + 2) % 3]) / 6.0);
  return points;
}

}  // namespace rad
