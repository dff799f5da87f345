#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "radiosity/core/rng.h"

namespace rad {

// n stratified points in [0,1)²: each column and each row of the n×n grid holds exactly one
// ("n-rooks", Shirley 1991), jittered inside its cell. Works for any n, unlike a √n×√n grid.
inline void nRooks(int n, Rng& rng, std::vector<std::pair<double, double>>& points) {
  points.resize(n);
  for (int i = 0; i < n; ++i) points[i] = {(i + rng.uniform()) / n, (i + rng.uniform()) / n};
  for (int i = n - 1; i > 0; --i)  // shuffle the second coordinate across the strata
    std::swap(points[i].second, points[rng.below(static_cast<uint32_t>(i + 1))].second);
}

}  // namespace rad
