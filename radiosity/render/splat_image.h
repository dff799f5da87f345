#pragma once

#include <vector>

#include "radiosity/core/image.h"

namespace rad {

// What light tracing (BDPT's t = 1 strategies) adds to pixels other than the one whose sample
// made the light path: per pixel the sum of the splatted values and of their squares (for the
// variance estimate), for the full image and for each bin of a path binning. One per thread.
struct SplatImage {
  ImageRgb sum, sumSquares;
  std::vector<ImageRgb> binSum, binSumSquares;

  SplatImage(int width, int height, int bins)
      : sum(width, height),
        sumSquares(width, height),
        binSum(bins, ImageRgb(width, height)),
        binSumSquares(bins, ImageRgb(width, height)) {}
  // `bin` -1: the value belongs to no bin (it still counts in the full image).
  void add(int x, int y, const Rgb& value, int bin) {
    sum.at(x, y) += value;
    sumSquares.at(x, y) += value * value;
    if (bin < 0) return;
    binSum[bin].at(x, y) += value;
    binSumSquares[bin].at(x, y) += value * value;
  }
};

}  // namespace rad
