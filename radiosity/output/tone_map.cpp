#include "radiosity/output/tone_map.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "radiosity/core/check.h"

namespace rad {

double srgbEncode(double linear) {
  // NaN compares false everywhere: send it to black rather than into pow().
  if (!(linear > 0)) return 0.0;
  if (linear >= 1) return 1.0;
  if (linear <= 0.0031308) return 12.92 * linear;
  return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

ToneMap ToneMap::autoExposure(const std::vector<Rgb>& radiance,
                              const std::vector<double>& weights) {
  if (!weights.empty()) RAD_CHECK_EQ(weights.size(), radiance.size());
  std::vector<std::pair<double, double>> samples;  // (luminance, weight)
  samples.reserve(radiance.size());
  double total = 0;
  for (size_t i = 0; i < radiance.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    RAD_CHECK_MSG(w >= 0 && std::isfinite(w), "ToneMap::autoExposure: weight " + std::to_string(w) +
                                                  " of value " + std::to_string(i) +
                                                  " is negative or not finite");
    const double y = radiance[i].luminance();
    // Black surfaces would drag the percentile towards zero and over-expose everything else.
    if (!(y > 0) || !std::isfinite(y) || w == 0) continue;
    samples.emplace_back(y, w);
    total += w;
  }
  if (samples.empty()) return ToneMap{1.0};

  std::sort(samples.begin(), samples.end());
  const double target = 0.99 * total;
  double cumulative = 0;
  double percentile = samples.back().first;
  for (const auto& [y, w] : samples) {
    cumulative += w;
    if (cumulative >= target) {
      percentile = y;
      break;
    }
  }
  return ToneMap{1.0 / percentile};
}

std::array<std::uint8_t, 3> ToneMap::toSrgb8(const Rgb& radiance) const {
  std::array<std::uint8_t, 3> out{};
  for (int c = 0; c < 3; ++c) {
    // srgbEncode clamps to [0, 1] (and maps NaN to 0), so the rounded value fits a byte.
    const double encoded = srgbEncode(exposure * radiance[c]);
    out[c] = static_cast<std::uint8_t>(std::lround(255.0 * encoded));
  }
  return out;
}

}  // namespace rad
