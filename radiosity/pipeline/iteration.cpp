#include "radiosity/pipeline/iteration.h"

#include <algorithm>
#include <cmath>

#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/seconds_since.h"

namespace rad {

IterationLimits iterationLimits(const SolveOptions& options, int elements,
                                std::chrono::steady_clock::time_point start) {
  IterationLimits limits;
  limits.tolerance = options.tolerance;
  limits.maxIterations = options.maxIterations > 0 ? options.maxIterations
                                                   : defaultMaxIterations(options.solver, elements);
  if (options.solver == SolverKind::Jacobi && options.bounces >= 0) {
    limits.bounces = options.bounces;
    limits.maxIterations = options.bounces;
    limits.tolerance = 0;  // exactly that many bounces
  }
  limits.timeLimit = options.timeLimit;
  limits.start = start;
  return limits;
}

StopReason iterate(Solver& solver, const IterationLimits& limits,
                   std::vector<std::vector<Rgb>>* bounceTerms) {
  Progress progress("solve (" + solver.name() + ")", 0, "iterations");
  const double startMeasure = std::max(solver.progress(), 1e-300);
  const auto elapsed = [&] { return secondsSince(limits.start); };
  std::vector<Rgb> previous;
  if (bounceTerms) bounceTerms->push_back(previous = solver.solution());  // B_0 = E
  bool outOfTime = false;
  while (solver.iterations() < limits.maxIterations && solver.progress() > limits.tolerance) {
    throwIfInterrupted();
    if (limits.timeLimit > 0 && elapsed() >= limits.timeLimit) {
      outOfTime = true;  // keep the solution reached so far, flagged as not converged
      break;
    }
    solver.step();
    progress.advance();
    if (bounceTerms) {
      std::vector<Rgb> term = solver.solution();
      for (size_t e = 0; e < term.size(); ++e) term[e] -= previous[e];
      previous = solver.solution();
      bounceTerms->push_back(std::move(term));
    }
    if (limits.tolerance > 0 && solver.progress() > 0) {
      // Fraction of the way, on a log scale, from the starting measure to the tolerance.
      const double f =
          std::log(startMeasure / solver.progress()) / std::log(startMeasure / limits.tolerance);
      progress.setFraction(std::clamp(f, 0.0, 1.0),
                           solver.progressMeasure() + " " + formatNumber(solver.progress()));
    }
  }
  const StopReason reason =
      outOfTime             ? StopReason::TimeLimit
      : limits.bounces >= 0 ? (solver.iterations() == limits.bounces ? StopReason::Bounces
                                                                     : StopReason::IterationLimit)
                            : (solver.progress() <= limits.tolerance ? StopReason::Tolerance
                                                                     : StopReason::IterationLimit);
  progress.finish(solver.progressMeasure() + " " + formatNumber(solver.progress()) +
                  (converged(reason) ? "" : " (not converged)"));
  return reason;
}

void reportSolver(const Solver& solver, SolveReport& report) {
  report.solverName = solver.name();
  report.progressMeasure = solver.progressMeasure();
  report.iterations = solver.iterations();
  report.finalProgress = solver.progress();
}

}  // namespace rad
