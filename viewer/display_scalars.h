#pragma once

#include <vtkPolyData.h>
#include <vtkScalarsToColors.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

#include "radiosity/output/tone_map.h"

namespace rad {

// What the viewer colours the mesh by.
enum class DisplayScalar {
  Colour,
  Radiance,
  RadiosityRed,
  RadiosityGreen,
  RadiosityBlue,
  Unshot,
  Area,
  Level,
  Patch
};
inline constexpr int displayScalarCount = 9;

struct DisplayScalarInfo {
  const char* key;    // command-line name
  const char* title;  // scalar-bar title, with units
  bool smoothable;    // false for ids and levels, which are never interpolated
};
const DisplayScalarInfo& displayScalarInfo(DisplayScalar scalar);
// "colour", "radiance", "B_r", "B_g", "B_b", "unshot", "area", "level", "patch"; InputError
// otherwise.
DisplayScalar parseDisplayScalar(const std::string& key);
// "colour | radiance | ... | patch": the keys of the one table, for --help and errors.
std::string displayScalarNames();

// Per-cell values of a solution PolyData for a scalar (Colour: the radiance's luminance).
std::vector<double> cellScalars(vtkPolyData* solution, DisplayScalar scalar);

// The colour map of a scalar over its values: for Colour, a grey ramp that reproduces the tone
// map (so the scalar bar reads radiance in physical units); ids get distinct colours; the rest a
// cool-to-warm map over [min, max].
vtkSmartPointer<vtkScalarsToColors> scalarColours(DisplayScalar scalar,
                                                  const std::vector<double>& values,
                                                  const ToneMap& toneMap);

}  // namespace rad
