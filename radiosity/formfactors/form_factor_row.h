#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// The non-zero form factors F_ij from one element i to the elements j it reaches, sorted by j.
// `escaped` is the part of i's hemisphere that reached no front face (open scene, back faces):
// with it, the row sums to 1.
//
// Extended form factors (through mirrors and glass) carry the specular reflectance or
// transmittance they picked up, per channel: then `tinted` holds, for each target, the
// per-channel factor, and `values` the plain (untinted) fraction of rays. Rows that met no
// specular surface leave `tinted` empty.
//
// Rows that sample each receiver at several points (analytic factors at the 3 Gauss points) may
// keep the fraction at each point in `points` (same order as the element's receiver points;
// values[k] is their mean), so a solver can hold a linear field per element, not just its mean.
// Empty when the row does not resolve its receivers.
struct FormFactorRow {
  std::vector<int> targets;
  std::vector<double> values;
  std::vector<Rgb> tinted;
  std::vector<std::array<float, 3>> points;
  double escaped = 0;

  Rgb factor(size_t k) const { return tinted.empty() ? Rgb::all(values[k]) : tinted[k]; }

  double sum() const {
    double s = 0;
    for (double v : values) s += v;
    return s;
  }
  double valueFor(int target) const;  // 0 when the target is not in the row
};

// How an update changes a kept hemisphere row (HemisphereFormFactors::updateRow), in rays: each
// factor of the row is a count of its `counted` rays over `counted`. `escaped` is the change in
// the escaped count; `counts`, per target whose count changes, by how much (sorted by target, no
// zero changes). None of either: the row is as it was.
struct RowChanges {
  int counted = 0;
  int64_t escaped = 0;
  std::vector<std::pair<int, int>> counts;
  bool none() const { return escaped == 0 && counts.empty(); }
};

}  // namespace rad
