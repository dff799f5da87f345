#pragma once

// Closed-form form factors from Howell's catalogue (../shared/REFERENCES.md), used as the
// independent reference for the ray-cast estimates.
#include <cmath>

namespace rad::reference {

// Identical, directly opposed parallel rectangles a×b at distance c.
inline double parallelRectangles(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x2 = x * x, y2 = y * y;
  return 2.0 / (M_PI * x * y) *
         (std::log(std::sqrt((1 + x2) * (1 + y2) / (1 + x2 + y2))) +
          x * std::sqrt(1 + y2) * std::atan(x / std::sqrt(1 + y2)) +
          y * std::sqrt(1 + x2) * std::atan(y / std::sqrt(1 + x2)) - x * std::atan(x) -
          y * std::atan(y));
}

// Perpendicular rectangles sharing an edge of length l: from rectangle 1 (l×w) to 2 (l×h).
inline double perpendicularRectangles(double l, double w, double h) {
  const double H = h / l, W = w / l;
  const double H2 = H * H, W2 = W * W, s = std::sqrt(H2 + W2);
  const double a = (1 + W2) * (1 + H2) / (1 + W2 + H2);
  const double b = std::pow(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2)), W2);
  const double c = std::pow(H2 * (1 + W2 + H2) / ((1 + H2) * (W2 + H2)), H2);
  return 1.0 / (M_PI * W) *
         (W * std::atan(1 / W) + H * std::atan(1 / H) - s * std::atan(1 / s) +
          0.25 * std::log(a * b * c));
}

}  // namespace rad::reference
