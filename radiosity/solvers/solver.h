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
  // The irradiance (W/m²) each element receives straight from `emission` (an exitance per
  // element, W/m²) through this solver's own form factors: the gathering rows' Σ_j F_ij E_j, or
  // the shooters' rows spread as one shot of their emission. So ρ × it is the part of solution()
  // that came from `emission` in its first bounce, by the same estimator: its noise cancels in
  // B − E − ρ × it. Empty where the solver's transport cannot be applied to another emission
  // (hierarchical links, whose clusters show their own B).
  virtual std::vector<Rgb> irradianceFrom(const std::vector<Rgb>& emission) = 0;
};

}  // namespace rad
