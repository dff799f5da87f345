#pragma once

#include <vector>

#include "radiosity/core/check.h"
#include "radiosity/core/rgb.h"

namespace rad {

// A linear RGB image in double precision (radiance, W·m⁻²·sr⁻¹, for renders and lightmaps).
// Row-major, row 0 at the top, as in EXR and PNG files.
struct ImageRgb {
  int width = 0, height = 0;
  std::vector<Rgb> pixels;

  ImageRgb() = default;
  ImageRgb(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h) {
    RAD_CHECK_MSG(w > 0 && h > 0, "image size " + std::to_string(w) + "×" + std::to_string(h));
  }
  Rgb& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const Rgb& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

}  // namespace rad
