#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "radiosity/core/hemisphere.h"

namespace rad {

// cos(2 pi u) and sin(2 pi u) for u in [0, 1] in float, as plain arithmetic that vectorises
// (std::sincos does not): u is split into a quarter turn q and a remainder angle a in
// [-pi/4, pi/4], whose sine and cosine come from Cephes' sinf/cosf polynomials (error about one
// float ulp), then the quarter turn swaps and negates them.
inline void turnCosSin(float u, float& c, float& s) {
  const float y = 4.0f * u;
  const int q = static_cast<int>(y + 0.5f);  // nearest quarter turn (y >= 0)
  const float a = (y - static_cast<float>(q)) * 1.57079632679489662f;
  const float z = a * a;
  const float sa = a + a * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
  const float ca =
      1.0f - 0.5f * z +
      z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f));
  const bool odd = (q & 1) != 0;
  const float cq = odd ? sa : ca, sq = odd ? ca : sa;
  c = ((q + 1) & 2) ? -cq : cq;
  s = (q & 2) ? -sq : sq;
}

// Uniform point on a triangle from a point of the unit square (area-preserving warp), so
// stratified square samples stay stratified on the triangle.
inline Eigen::Vector3d uniformPointOnTriangle(const std::array<Eigen::Vector3d, 3>& c, double u,
                                              double v) {
  const double su = std::sqrt(u);
  return (1.0 - su) * c[0] + su * (1.0 - v) * c[1] + su * v * c[2];
}

}  // namespace rad
