#include "radiosity/render/adaptive_allocation.h"

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// A pixel's neighbourhood in the first pass: the largest spread among its neighbours (its guide),
// which neighbour holds it, and the largest without that one.
struct Neighbourhood {
  double guide = 0, second = 0;
  size_t holder = SIZE_MAX;
};

template <typename Fn>
void forEachNeighbour(int x, int y, int width, int height, Fn fn) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      fn(static_cast<size_t>(ny) * width + nx);
    }
}

}  // namespace

AdaptiveAllocation allocateAdaptiveSamples(const std::vector<double>& sigma, int width, int height,
                                           int64_t budget, int maxPerPixel) {
  const size_t pixels = static_cast<size_t>(width) * height;
  RAD_CHECK_EQ(sigma.size(), pixels);
  RAD_CHECK_GE(budget, 0);
  std::vector<Neighbourhood> near(pixels);
  double guideSum = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Neighbourhood& n = near[static_cast<size_t>(y) * width + x];
      forEachNeighbour(x, y, width, height, [&](size_t q) {
        if (sigma[q] > n.guide) {
          n.second = n.guide;
          n.guide = sigma[q];
          n.holder = q;
        } else {
          n.second = std::max(n.second, sigma[q]);
        }
      });
      guideSum += n.guide;
    }
  AdaptiveAllocation out;
  out.extra.assign(pixels, 0);
  if (pixels == 0 || budget == 0) return out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = static_cast<size_t>(y) * width + x;
      // The sum of the guides as if this pixel had no spread (its neighbours' guides without it):
      // then neither the share's numerator nor its denominator depends on the pixel's own samples.
      double sumWithout = guideSum;
      forEachNeighbour(x, y, width, height, [&](size_t q) {
        if (near[q].holder == p) sumWithout -= near[q].guide - near[q].second;
      });
      const double share =
          sumWithout > 0 ? budget * near[p].guide / sumWithout : double(budget) / pixels;
      out.extra[p] = static_cast<int>(std::min<double>(maxPerPixel, std::floor(share + 0.5)));
      out.total += out.extra[p];
    }
  return out;
}

}  // namespace rad
