#pragma once

#include <vector>

namespace rad {

// The non-zero form factors F_ij from one element i to the elements j it reaches, sorted by j.
// `escaped` is the part of i's hemisphere that reached no front face (open scene, back faces):
// with it, the row sums to 1.
struct FormFactorRow {
  std::vector<int> targets;
  std::vector<double> values;
  double escaped = 0;

  double sum() const {
    double s = 0;
    for (double v : values) s += v;
    return s;
  }
  double valueFor(int target) const;  // 0 when the target is not in the row
};

}  // namespace rad
