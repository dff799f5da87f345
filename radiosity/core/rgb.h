#pragma once

#include <algorithm>
#include <cmath>

namespace rad {

// Linear RGB triple in double precision: reflectance, emission, radiosity or power per channel.
struct Rgb {
  double r = 0, g = 0, b = 0;

  constexpr Rgb() = default;
  constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
  static constexpr Rgb all(double v) { return {v, v, v}; }

  constexpr double operator[](int c) const { return c == 0 ? r : (c == 1 ? g : b); }
  double& operator[](int c) { return c == 0 ? r : (c == 1 ? g : b); }

  constexpr Rgb operator+(const Rgb& o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Rgb operator-(const Rgb& o) const { return {r - o.r, g - o.g, b - o.b}; }
  constexpr Rgb operator*(const Rgb& o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Rgb operator*(double s) const { return {r * s, g * s, b * s}; }
  constexpr Rgb operator/(double s) const { return {r / s, g / s, b / s}; }
  Rgb& operator+=(const Rgb& o) {
    r += o.r;
    g += o.g;
    b += o.b;
    return *this;
  }
  Rgb& operator-=(const Rgb& o) {
    r -= o.r;
    g -= o.g;
    b -= o.b;
    return *this;
  }
  Rgb& operator*=(double s) {
    r *= s;
    g *= s;
    b *= s;
    return *this;
  }

  constexpr double sum() const { return r + g + b; }
  constexpr double maxComponent() const { return std::max(r, std::max(g, b)); }
  constexpr double minComponent() const { return std::min(r, std::min(g, b)); }
  constexpr bool isZero() const { return r == 0 && g == 0 && b == 0; }
  bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
  // Rec. 709 luminance weights, used for tone mapping and for ranking shooters.
  constexpr double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
};

inline constexpr Rgb operator*(double s, const Rgb& c) { return c * s; }

}  // namespace rad
