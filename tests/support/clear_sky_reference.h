#pragma once

// The CIE standard clear sky (CIE S 011/E:2003 type 12) written out independently of
// radiosity/scene/light_shapes, and its irradiance on an open upward plane integrated numerically:
// the reference the solve and render tests hold the sampled estimates to.
#include <algorithm>
#include <cmath>

namespace rad::testing {

// E / L_z = ∫ L(θ, γ)/L_z cosθ dω over the sky, the sun at `sunElevationDegrees`, by the midpoint
// rule on a 0.05° × 0.1° grid (φ from the sun's azimuth).
inline double clearSkyUpwardIrradiance(double sunElevationDegrees) {
  const double thetaSun = M_PI / 2 - sunElevationDegrees * M_PI / 180;
  const auto f = [](double x) {
    return 0.91 + 10 * std::exp(-3 * x) + 0.45 * std::cos(x) * std::cos(x);
  };
  const int nt = 1800, np = 3600;
  double sum = 0;
  for (int i = 0; i < nt; ++i) {
    const double theta = (i + 0.5) * (M_PI / 2) / nt;
    for (int j = 0; j < np; ++j) {
      const double phi = (j + 0.5) * 2 * M_PI / np;  // from the sun's azimuth
      const double cosGamma = std::cos(theta) * std::cos(thetaSun) +
                              std::sin(theta) * std::sin(thetaSun) * std::cos(phi);
      const double gamma = std::acos(std::clamp(cosGamma, -1.0, 1.0));
      sum += f(gamma) * (1 - std::exp(-0.32 / std::cos(theta))) * std::cos(theta) * std::sin(theta);
    }
  }
  return sum * (M_PI / 2 / nt) * (2 * M_PI / np) / (f(thetaSun) * (1 - std::exp(-0.32)));
}

}  // namespace rad::testing
