// Compares renders for bench/render_error_vs_time.py (no numpy here, so EXR arithmetic in C++).
//   render_compare rmse IMAGE.exr REFERENCE.exr     → relative RMSE sqrt(Σ(a−r)²/Σr²), mean ratio,
//       and the same two over the pixels away from the emitters seen directly ("surfaces": every
//       pixel farther than one pixel from one whose reference value is at least half the
//       brightest), where the emitters' pixels no longer dominate Σr²
//   render_compare average A.exr B.exr OUT.exr      → OUT = (A+B)/2; prints the relative RMSE of
//       OUT's noise, estimated as ½·rmse(A, B) (two independent renders of the same image)
//   render_compare pfm IMAGE.exr OUT.pfm             → the same pixels as a PFM (for numpy plots)
//   render_compare relmse IMAGE.exr REFERENCE.exr REFERENCE_VARIANCE.exr
//       → per-pixel relative RMSE sqrt(mean over pixels and channels of ((a−r)² − v)/(r² + ε)),
//       v the variance of the reference's own pixel mean (its noise, removed: for independent a
//       and reference, E[(a−ref)²] = E[(a−r)²] + Var(ref)), ε = (0.1·mean(r))²; then the same
//       without removing v, ε, and the reference's own noise over the "surfaces" pixels of
//       `rmse`, sqrt(Σ v / Σ r²) there (to remove from that metric in quadrature)
//   render_compare plain IMAGE.exr REFERENCE.exr VARIANCE.exr [VARIANCE2.exr]
//       → the plain relative RMSE of bench/peer (issue 17): RMSE / mean of the reference, over all
//       pixels and channels, with the noise of the variance images removed (their sum Σv
//       subtracted from Σ(a−r)²: the reference's, and IMAGE's own when it is the mean of two
//       halves, which leaves the systematic difference alone) and raw; the mean ratio; then the
//       same three over the "surfaces" pixels of `rmse`
//   render_compare halves A.exr B.exr OUT.exr OUT_VARIANCE.exr
//       → OUT = (A+B)/2 and, per pixel, the variance of that mean, estimated without bias as
//       (A−B)²/4 (A, B independent renders of the same image with the same settings); prints the
//       image-wide relative RMSE of OUT's noise and its per-pixel relative RMSE (ε as above)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

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

// ε of the per-pixel relative error: a pixel darker than a tenth of the image's mean counts its
// error against that tenth instead of its own value (so black or nearly black pixels do not blow
// the mean up), and the metric does not depend on the radiance's units.
double relativeEpsilon(const rad::ImageRgb& r) {
  const double floor = 0.1 * meanValue(r);
  return floor * floor;
}

// Mean over pixels and channels of (squared error − reference variance) / (r² + ε).
double relativeMse(const rad::ImageRgb& a, const rad::ImageRgb& r, const rad::ImageRgb* variance,
                   double epsilon) {
  double sum = 0;
  for (size_t p = 0; p < r.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double d = a.pixels[p][c] - r.pixels[p][c];
      const double v = variance ? variance->pixels[p][c] : 0.0;
      sum += (d * d - v) / (r.pixels[p][c] * r.pixels[p][c] + epsilon);
    }
  return sum / (3.0 * r.pixels.size());
}

// sqrt(mean of (a−r)² − v) / mean(r) and the same without v, over the pixels `mask` keeps.
std::pair<double, double> plainRelativeRmse(const rad::ImageRgb& a, const rad::ImageRgb& r,
                                            const rad::ImageRgb& variance,
                                            const std::vector<char>& mask) {
  double diff2 = 0, noise2 = 0, sum = 0;
  long count = 0;
  for (size_t p = 0; p < r.pixels.size(); ++p) {
    if (!mask[p]) continue;
    const rad::Rgb d = a.pixels[p] - r.pixels[p];
    diff2 += (d * d).sum();
    noise2 += variance.pixels[p].sum();
    sum += r.pixels[p].sum();
    count += 3;
  }
  const double mean = sum / count;
  return {std::sqrt(std::max(0.0, diff2 - noise2) / count) / mean, std::sqrt(diff2 / count) / mean};
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
    if (mode == "relmse" && argc == 5) {
      const rad::ImageRgb a = rad::readExr(argv[2]), r = rad::readExr(argv[3]),
                          v = rad::readExr(argv[4]);
      requireSameSize(a, r);
      requireSameSize(v, r);
      const double epsilon = relativeEpsilon(r);
      // The noise-removed mean may come out below 0 when a is as noisy as the reference: report 0.
      const std::vector<char> surfaces = surfaceMask(r);
      double noise2 = 0, ref2 = 0;
      for (size_t p = 0; p < r.pixels.size(); ++p)
        if (surfaces[p]) {
          noise2 += v.pixels[p].sum();
          ref2 += (r.pixels[p] * r.pixels[p]).sum();
        }
      std::printf("%.6f %.6f %.6g %.6f\n", std::sqrt(std::max(0.0, relativeMse(a, r, &v, epsilon))),
                  std::sqrt(relativeMse(a, r, nullptr, epsilon)), epsilon,
                  std::sqrt(noise2 / ref2));
      return 0;
    }
    if (mode == "plain" && (argc == 5 || argc == 6)) {
      const rad::ImageRgb a = rad::readExr(argv[2]), r = rad::readExr(argv[3]);
      rad::ImageRgb v = rad::readExr(argv[4]);
      requireSameSize(a, r);
      requireSameSize(v, r);
      if (argc == 6) {
        const rad::ImageRgb v2 = rad::readExr(argv[5]);
        requireSameSize(v2, r);
        for (size_t p = 0; p < v.pixels.size(); ++p) v.pixels[p] = v.pixels[p] + v2.pixels[p];
      }
      const std::vector<char> all(r.pixels.size(), 1), surfaces = surfaceMask(r);
      const auto [whole, wholeRaw] = plainRelativeRmse(a, r, v, all);
      const auto [surface, surfaceRaw] = plainRelativeRmse(a, r, v, surfaces);
      std::printf("%.6f %.6f %.6f %.6f %.6f %.6f\n", whole, wholeRaw, meanRatio(a, r, all), surface,
                  surfaceRaw, meanRatio(a, r, surfaces));
      return 0;
    }
    if (mode == "halves" && argc == 6) {
      const rad::ImageRgb a = rad::readExr(argv[2]), b = rad::readExr(argv[3]);
      requireSameSize(a, b);
      rad::ImageRgb mean(a.width, a.height), variance(a.width, a.height);
      for (size_t p = 0; p < a.pixels.size(); ++p) {
        mean.pixels[p] = 0.5 * (a.pixels[p] + b.pixels[p]);
        const rad::Rgb d = a.pixels[p] - b.pixels[p];
        variance.pixels[p] = 0.25 * (d * d);
      }
      rad::writeExr(argv[4], mean);
      rad::writeExr(argv[5], variance);
      // Per-pixel: the mean's own relative noise, sqrt(mean of v/(r² + ε)) = the relmse of a
      // noiseless image against it.
      std::printf("%.6f %.6f\n", 0.5 * relativeRmse(a, b),
                  std::sqrt(-relativeMse(mean, mean, &variance, relativeEpsilon(mean))));
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
    std::fprintf(
        stderr,
        "usage: render_compare rmse IMAGE REF | relmse IMAGE REF REF_VARIANCE | plain IMAGE REF "
        "VARIANCE [VARIANCE2] | average A B OUT | "
        "halves A B OUT OUT_VARIANCE | pfm IMAGE OUT\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
