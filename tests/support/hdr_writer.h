#pragma once

// Writes small Radiance HDR images for the environment-light tests: the header, then flat
// (uncompressed) RGBE pixels, rows top first. Values that are a power of two times an 8-bit
// mantissa (1, 0.5, 2, 3, …) come back exactly.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad::testing {

inline void writeHdr(const std::string& path, int width, int height,
                     const std::vector<Rgb>& pixels) {
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
  for (const Rgb& p : pixels) {
    const double m = std::max({p.r, p.g, p.b});
    unsigned char rgbe[4] = {0, 0, 0, 0};
    if (m > 1e-32) {
      int e = 0;
      const double scale = std::frexp(m, &e) * 256 / m;  // the largest channel's mantissa × 256
      rgbe[0] = static_cast<unsigned char>(p.r * scale);
      rgbe[1] = static_cast<unsigned char>(p.g * scale);
      rgbe[2] = static_cast<unsigned char>(p.b * scale);
      rgbe[3] = static_cast<unsigned char>(e + 128);
    }
    out.write(reinterpret_cast<const char*>(rgbe), 4);
  }
}

}  // namespace rad::testing
