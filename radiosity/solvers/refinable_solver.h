#pragma once

#include <array>
#include <functional>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// A solver that carries on after the receiving elements were refined, without starting over:
// what adaptive refinement needs. It also holds B at each element's 3 receiver points, from which
// the displayed (interpolated) radiance is judged.
class RefinableSolver : public Solver {
 public:
  // B at each element's 3 receiver points, whose mean is solution().
  virtual const std::vector<std::array<Rgb, 3>>& pointSolution() const = 0;
  // The mesh's elements `changed` were replaced or added (shooters unchanged); the caller already
  // updated the problem. elementToShooter gives the form factor at each of an element's 3
  // receiver points.
  virtual void elementsChanged(
      const std::vector<int>& changed,
      const std::function<std::array<double, 3>(int element, int shooter)>& elementToShooter) = 0;
};

}  // namespace rad
