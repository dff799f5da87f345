#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

namespace rad {

// Where a lightmap texel lies on its element, for spreading a bake's rays over the texel (a box
// filter, as Cycles' bake and the engines' lightmappers do) instead of taking its centre alone:
// the barycentrics at the texel's centre (or the element's point nearest it) and their change
// per texel step in x and y.
struct TexelFootprint {
  Eigen::Vector3d centre{1.0 / 3, 1.0 / 3, 1.0 / 3};
  Eigen::Vector3d perX = Eigen::Vector3d::Zero(), perY = Eigen::Vector3d::Zero();

  // The footprint of the texel whose centre has barycentrics `centre` on a triangle with corners
  // `texelCorners` in texel units. The barycentrics are affine in the texel
  // position, so their steps are constant over the triangle.
  static TexelFootprint of(const std::array<Eigen::Vector2d, 3>& texelCorners,
                           const Eigen::Vector3d& centre) {
    const Eigen::Vector2d e1 = texelCorners[1] - texelCorners[0],
                          e2 = texelCorners[2] - texelCorners[0];
    const double det = e1.x() * e2.y() - e1.y() * e2.x();
    TexelFootprint f;
    f.centre = centre;
    // A triangle of no area in texel space (scene UVs may hold one): its centre alone.
    if (!std::isfinite(1.0 / det)) return f;
    // b1 = (d.x e2.y − d.y e2.x) / det and b2 = (e1.x d.y − e1.y d.x) / det for d = p − t0.
    const double b1x = e2.y() / det, b1y = -e2.x() / det;
    const double b2x = -e1.y() / det, b2y = e1.x() / det;
    f.perX = {-b1x - b2x, b1x, b2x};
    f.perY = {-b1y - b2y, b1y, b2y};
    return f;
  }

  bool isPoint() const { return perX.isZero(0) && perY.isZero(0); }

  // Barycentrics at (u, v) ∈ [0, 1]² across the texel ((0.5, 0.5): the centre). Where the texel
  // reaches past the triangle the point is mirrored back into it (first coordinate into [0, 1],
  // second into [0, 1 − first]), so every point lies on the element and a texel inside it is
  // sampled uniformly.
  Eigen::Vector3d at(double u, double v) const {
    const Eigen::Vector3d b = centre + (u - 0.5) * perX + (v - 0.5) * perY;
    const double b1 = mirrorInto(b[1], 1.0);
    const double b2 = mirrorInto(b[2], 1.0 - b1);
    return {1.0 - b1 - b2, b1, b2};
  }

  // x reflected back and forth into [0, range] (0 for an empty range).
  static double mirrorInto(double x, double range) {
    if (!(range > 0)) return 0.0;
    const double period = 2.0 * range;
    double y = std::fmod(x, period);
    if (y < 0) y += period;
    return y > range ? period - y : y;
  }
};

}  // namespace rad
