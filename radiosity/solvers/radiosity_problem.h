#pragma once

#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// The per-element data of B_i = E_i + rho_i sum_j F_ij B_j, per RGB channel.
struct RadiosityProblem {
  std::vector<Rgb> emission;     // E_i: emitted radiosity, W/m² (pi × emitted radiance)
  std::vector<Rgb> reflectance;  // rho_i, each channel in [0, 1]
  std::vector<double> area;      // A_i, scene units²

  int size() const { return static_cast<int>(area.size()); }
  // Sum over elements and channels of A_i E_i: the scale every relative criterion divides by.
  double emittedPower() const;
  // Elements whose rows a gathering solver needs: those that reflect anything.
  std::vector<bool> reflecting() const;
};

// sum_i A_i |v_i|₁ / emittedPower(): relative size of a per-element radiosity vector.
double relativeToEmission(const RadiosityProblem& problem, const std::vector<Rgb>& values);

}  // namespace rad
