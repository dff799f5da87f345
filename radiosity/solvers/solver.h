#pragma once

#include <string>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// One interface for every method of solving the radiosity system. A driver calls step() until
// progress() falls below the tolerance (or an iteration budget runs out); solution() may be
// read at any time, e.g. for a live view.
class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;
  // One unit of work: a sweep (Gauss–Seidel), a bounce (Jacobi) or a shot (progressive).
  virtual void step() = 0;
  // The convergence measure, relative: residual over emission (Jacobi, Gauss–Seidel) or unshot
  // power over emitted power (progressive). 0 means exactly converged.
  virtual double progress() const = 0;
  virtual const std::vector<Rgb>& solution() const = 0;
  virtual int iterations() const = 0;
  // What progress() measures, for logs and summary.json.
  virtual std::string progressMeasure() const = 0;
};

}  // namespace rad
