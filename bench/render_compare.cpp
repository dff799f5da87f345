// Compares renders for bench/render_error_vs_time.py (no numpy here, so EXR arithmetic in C++).
//   render_compare rmse IMAGE.exr REFERENCE.exr     → relative RMSE sqrt(Σ(a−r)²/Σr²), mean ratio,
//       and the same two over the pixels away from the emitters seen directly ("surfaces": every
//       pixel farther than one pixel from one whose reference value is at least half the
//       brightest), where the emitters' pixels no longer dominate Σr²
//   render_compare average A.exr B.exr OUT.exr      → OUT = (A+B)/2; prints the relative RMSE of
//       OUT's noise, estimated as ½·rmse(A, B) (two independent renders of the same image)
//   render_compare pfm IMAGE.exr OUT.pfm             → the same pixels as a PFM (for numpy plots)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <algorithm>

#include "radiosity/output/image_io.h"

namespace {

double relativeRmse(const rad::ImageRgb& a, const rad::ImageRgb& r) {
  double diff2 = 0, ref2 = 0;
  for (size_t p = 0; p < r.pixels.size(); ++p) {
    const rad::Rgb d = a.pixels[p] - r.pixels[p];
    diff2 += (d * d).sum();
    ref2 += (r.pixels[p] * r.pixels[p]).sum();
  }
  return std::sqrt(diff2 / ref2);
}

double relativeRmse(const rad::ImageRgb& a, const rad::ImageRgb& r, const std::vector<char>& mask) {
  double diff2 = 0, ref2 = 0;
  for (size_t p = 0; p < r.pixels.size(); ++p) {
    if (!mask[p]) continue;
    const rad::Rgb d = a.pixels[p] - r.pixels[p];
    diff2 += (d * d).sum();
    ref2 += (r.pixels[p] * r.pixels[p]).sum();
  }
  return std::sqrt(diff2 / ref2);
}

double meanValue(const rad::ImageRgb& a) {
  double s = 0;
  for (const rad::Rgb& p : a.pixels) s += p.sum();
  return s / (3.0 * a.pixels.size());
}

double meanRatio(const rad::ImageRgb& a, const rad::ImageRgb& r, const std::vector<char>& mask) {
  double sa = 0, sr = 0;
  for (size_t p = 0; p < r.pixels.size(); ++p)
    if (mask[p]) {
      sa += a.pixels[p].sum();
      sr += r.pixels[p].sum();
    }
  return sa / sr;
}

// Pixels farther than one pixel (8-neighbourhood) from any pixel whose reference value (sum of
// channels) is at least half the image's brightest: the surfaces, without the emitters seen.
std::vector<char> surfaceMask(const rad::ImageRgb& r) {
  double brightest = 0;
  for (const rad::Rgb& p : r.pixels) brightest = std::max(brightest, p.sum());
  std::vector<char> mask(r.pixels.size(), 1);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      if (r.at(x, y).sum() < 0.5 * brightest) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < r.width && v < r.height)
            mask[static_cast<size_t>(v) * r.width + u] = 0;
        }
    }
  return mask;
}

void requireSameSize(const rad::ImageRgb& a, const rad::ImageRgb& b) {
  if (a.width != b.width || a.height != b.height) throw std::runtime_error("image sizes differ");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "rmse" && argc == 4) {
      const rad::ImageRgb a = rad::readExr(argv[2]), r = rad::readExr(argv[3]);
      requireSameSize(a, r);
      const std::vector<char> surfaces = surfaceMask(r);
      std::printf("%.6f %.6f %.6f %.6f\n", relativeRmse(a, r), meanValue(a) / meanValue(r),
                  relativeRmse(a, r, surfaces), meanRatio(a, r, surfaces));
      return 0;
    }
    if (mode == "average" && argc == 5) {
      const rad::ImageRgb a = rad::readExr(argv[2]), b = rad::readExr(argv[3]);
      requireSameSize(a, b);
      rad::ImageRgb out(a.width, a.height);
      for (size_t p = 0; p < a.pixels.size(); ++p)
        out.pixels[p] = 0.5 * (a.pixels[p] + b.pixels[p]);
      rad::writeExr(argv[4], out);
      std::printf("%.6f\n", 0.5 * relativeRmse(a, b));
      return 0;
    }
    if (mode == "pfm" && argc == 4) {
      // Portable float map: little-endian scale (negative), rows stored bottom to top.
      const rad::ImageRgb a = rad::readExr(argv[2]);
      std::FILE* f = std::fopen(argv[3], "wb");
      if (!f) throw std::runtime_error(std::string("cannot write ") + argv[3]);
      std::fprintf(f, "PF\n%d %d\n-1.0\n", a.width, a.height);
      for (int y = a.height - 1; y >= 0; --y)
        for (int x = 0; x < a.width; ++x) {
          const rad::Rgb& p = a.at(x, y);
          const float v[3] = {float(p.r), float(p.g), float(p.b)};
          std::fwrite(v, sizeof(float), 3, f);
        }
      if (std::fclose(f) != 0) throw std::runtime_error(std::string("cannot write ") + argv[3]);
      return 0;
    }
    std::fprintf(stderr, "usage: render_compare rmse IMAGE REF | average A B OUT | pfm IMAGE OUT\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
