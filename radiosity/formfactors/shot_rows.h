#pragma once

#include <string>

#include "radiosity/formfactors/form_factor_row.h"

namespace rad {

// What progressive shooting needs from form factors: who shoots (shooters: elements, or coarser
// patches that contain several elements) and, for a shooter s, which fraction of the power s
// emits reaches each receiving element j (row.targets are elements, row.values the fractions).
// Rows may be computed lazily, on a shooter's first shot.
class ShotRows {
 public:
  virtual ~ShotRows() = default;
  virtual int shooterCount() const = 0;
  virtual int shooterOf(int element) const = 0;
  virtual double shooterArea(int shooter) const = 0;
  virtual const FormFactorRow& powerFractions(int shooter) = 0;
  virtual std::string description() const = 0;
};

}  // namespace rad
