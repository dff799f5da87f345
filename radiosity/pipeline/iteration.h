#pragma once

#include <chrono>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// When the iterations stop: at the tolerance, after the iteration budget, or past the time limit
// (counted from `start`, the beginning of the solve). With Jacobi bounces, after exactly that
// many iterations whatever the residual.
struct IterationLimits {
  double tolerance = 0;
  int maxIterations = 0;
  int bounces = -1;      // >= 0: exactly this many iterations are the goal
  double timeLimit = 0;  // seconds; 0: none
  std::chrono::steady_clock::time_point start;
};
IterationLimits iterationLimits(const SolveOptions& options, int elements,
                                std::chrono::steady_clock::time_point start);

// Steps the solver until a limit stops it, with a progress line; with `bounceTerms`, appends
// B_0 = E and then each step's term B_k − B_{k−1} (the Jacobi iterates' Neumann terms).
StopReason iterate(Solver& solver, const IterationLimits& limits,
                   std::vector<std::vector<Rgb>>* bounceTerms = nullptr);

// The solver's name, measure, iteration count and final progress, into the report.
void reportSolver(const Solver& solver, SolveReport& report);

inline bool converged(StopReason reason) {
  return reason == StopReason::Tolerance || reason == StopReason::Bounces;
}

}  // namespace rad
