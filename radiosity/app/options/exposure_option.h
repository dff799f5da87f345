#pragma once

// --exposure X: the 8-bit outputs' exposure (display = clamp(X · L)), fixed instead of automatic.
// Every command that writes 8-bit images (render, compare, bake) reads it in every mode.
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "radiosity/output/tone_map.h"

namespace rad {

class ExposureOption {
 public:
  // `help`: what it exposes and the automatic rule it replaces.
  void add(CLI::App& command, const std::string& help);
  // InputError unless a given exposure is > 0.
  void check() const;
  // The given exposure, else the command's automatic one.
  ToneMap toneMap(const std::function<ToneMap()>& automatic) const;
  // The given exposure; none: automatic.
  const std::optional<double>& value() const { return value_; }

 private:
  std::optional<double> value_;
};

}  // namespace rad
