#include "radiosity/solvers/radiosity_problem.h"

#include <cmath>

#include "radiosity/core/compensated_sum.h"

namespace rad {

double RadiosityProblem::emittedPower() const {
  CompensatedSum sum;
  for (int i = 0; i < size(); ++i) sum += area[i] * emission[i].sum();
  return sum.value();
}

std::vector<bool> RadiosityProblem::reflecting() const {
  std::vector<bool> needed(size());
  for (int i = 0; i < size(); ++i) needed[i] = reflectance[i].maxComponent() > 0;
  return needed;
}

double relativeToEmission(const RadiosityProblem& problem, const std::vector<Rgb>& values) {
  CompensatedSum sum;
  for (int i = 0; i < problem.size(); ++i)
    sum += problem.area[i] *
           (std::fabs(values[i].r) + std::fabs(values[i].g) + std::fabs(values[i].b));
  const double emitted = problem.emittedPower();
  return emitted > 0 ? sum.value() / emitted : 0.0;
}

}  // namespace rad
