#include "radiosity/app/options/exposure_option.h"

#include "radiosity/core/errors.h"

namespace rad {

void ExposureOption::add(CLI::App& command, const std::string& help) {
  command.add_option("--exposure", value_, help);
}

void ExposureOption::check() const {
  if (value_ && !(*value_ > 0)) throw InputError("--exposure must be > 0");
}

ToneMap ExposureOption::toneMap(const std::function<ToneMap()>& automatic) const {
  return value_ ? ToneMap{*value_} : automatic();
}

}  // namespace rad
