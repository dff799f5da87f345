#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// sRGB opto-electronic transfer function (IEC 61966-2-1): linear [0, 1] → encoded [0, 1].
// 12.92·x for x ≤ 0.0031308, else 1.055·x^(1/2.4) − 0.055. Input outside [0, 1] is clamped.
double srgbEncode(double linear);

// Maps linear radiance (W·m⁻²·sr⁻¹) to 8-bit display colour for baked vertex colours and
// previews. The operator, per channel:
//   display = clamp(exposure × radiance, 0, 1), then srgbEncode, then round(255 × value).
// A single global exposure keeps ratios between surfaces intact (no local adaptation), so a
// viewer can undo it exactly: the float radiance stays in the outputs beside the colours.
struct ToneMap {
  double exposure = 1.0;

  // Exposure that maps the 99th percentile of luminance (Rgb::luminance) to 1.0, so only the
  // brightest 1% (emitters, hot spots) saturate. The percentile is weighted (typically by
  // element area, so a finely meshed corner does not dominate): entries are sorted by luminance
  // and the chosen value is the smallest luminance at which the cumulative weight reaches 99% of
  // the total. Only entries with finite luminance > 0 and weight > 0 take part; if none do, the
  // exposure is 1. `weights` is empty (all entries weigh the same) or one per radiance entry;
  // a size mismatch or a negative or non-finite weight is a bug (RAD_CHECK: CheckFailure).
  static ToneMap autoExposure(const std::vector<Rgb>& radiance, const std::vector<double>& weights);

  // The operator above on one radiance value; NaN channels give 0.
  std::array<std::uint8_t, 3> toSrgb8(const Rgb& radiance) const;
};

}  // namespace rad
