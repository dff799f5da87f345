#include "viewer/display_scalars.h"

#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>

#include "radiosity/core/errors.h"
#include "viewer/solution_polydata.h"

namespace rad {
namespace {

const DisplayScalarInfo infos[displayScalarCount] = {
    {"colour", "L tone-mapped\n(W/m^2/sr)", true},
    {"radiance", "L luminance\n(W/m^2/sr)", true},
    {"B_r", "B red\n(W/m^2)", true},
    {"B_g", "B green\n(W/m^2)", true},
    {"B_b", "B blue\n(W/m^2)", true},
    {"unshot", "unshot power\nluminance (W)", true},
    {"area", "element area\n(m^2)", false},
    {"level", "refinement\nlevel", false},
    {"patch", "patch id", false},
};

double luminance(vtkDataArray* a, vtkIdType i) {
  return 0.2126 * a->GetComponent(i, 0) + 0.7152 * a->GetComponent(i, 1) +
         0.0722 * a->GetComponent(i, 2);
}

}  // namespace

const DisplayScalarInfo& displayScalarInfo(DisplayScalar scalar) {
  return infos[static_cast<int>(scalar)];
}

std::string displayScalarNames() {
  std::string names;
  for (const DisplayScalarInfo& info : infos)
    names += (names.empty() ? "" : " | ") + std::string(info.key);
  return names;
}

DisplayScalar parseDisplayScalar(const std::string& key) {
  for (int i = 0; i < displayScalarCount; ++i)
    if (key == infos[i].key) return static_cast<DisplayScalar>(i);
  throw InputError("unknown --scalar '" + key + "' (expected " + displayScalarNames() + ")");
}

std::vector<double> cellScalars(vtkPolyData* solution, DisplayScalar scalar) {
  vtkCellData* cd = solution->GetCellData();
  const vtkIdType n = solution->GetNumberOfCells();
  std::vector<double> v(n);
  vtkDataArray* a = nullptr;
  int component = 0;
  bool lum = false;
  switch (scalar) {
    case DisplayScalar::Colour:
    case DisplayScalar::Radiance:
      a = cd->GetArray(solution_array::radiance), lum = true;
      break;
    case DisplayScalar::RadiosityRed:
      a = cd->GetArray(solution_array::radiosity), component = 0;
      break;
    case DisplayScalar::RadiosityGreen:
      a = cd->GetArray(solution_array::radiosity), component = 1;
      break;
    case DisplayScalar::RadiosityBlue:
      a = cd->GetArray(solution_array::radiosity), component = 2;
      break;
    case DisplayScalar::Unshot:
      a = cd->GetArray(solution_array::unshot), lum = true;
      break;
    case DisplayScalar::Area:
      a = cd->GetArray(solution_array::area);
      break;
    case DisplayScalar::Level:
      a = cd->GetArray(solution_array::level);
      break;
    case DisplayScalar::Patch:
      a = cd->GetArray(solution_array::patch);
      break;
  }
  for (vtkIdType i = 0; a && i < n; ++i)
    v[i] = lum ? luminance(a, i) : a->GetComponent(i, component);
  return v;
}

vtkSmartPointer<vtkScalarsToColors> scalarColours(DisplayScalar scalar,
                                                  const std::vector<double>& values,
                                                  const ToneMap& toneMap) {
  double lo = 0, hi = 1;
  if (!values.empty()) {
    const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
    lo = *mn, hi = *mx;
  }
  if (!(hi > lo)) hi = lo + 1;

  if (scalar == DisplayScalar::Colour) {
    // Radiance from 0 to where the exposure saturates, through the same sRGB curve.
    auto lut = vtkSmartPointer<vtkLookupTable>::New();
    const int n = 256;
    lut->SetNumberOfTableValues(n);
    lut->SetRange(0, 1.0 / toneMap.exposure);
    for (int i = 0; i < n; ++i) {
      const double g = srgbEncode(static_cast<double>(i) / (n - 1));
      lut->SetTableValue(i, g, g, g, 1.0);
    }
    lut->Build();
    return lut;
  }
  if (scalar == DisplayScalar::Patch || scalar == DisplayScalar::Level) {
    // One colour per integer value; golden-ratio hue steps keep neighbouring ids apart. The table
    // is capped (ids past it share its last colour): a file's ids must not decide its size.
    constexpr double maxColours = 65536;
    const int count = static_cast<int>(std::lround(std::min(hi - lo, maxColours - 1))) + 1;
    auto lut = vtkSmartPointer<vtkLookupTable>::New();
    lut->SetNumberOfTableValues(count);
    lut->SetRange(lo - 0.5, lo + count - 0.5);
    for (int i = 0; i < count; ++i) {
      double rgb[3];
      const double hue = std::fmod(0.61803398875 * i, 1.0);
      vtkMath::HSVToRGB(hue, 0.65, 0.95, rgb, rgb + 1, rgb + 2);
      lut->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
    }
    lut->Build();
    return lut;
  }
  // Emitters are orders of magnitude brighter than what they light: span the range up to the
  // 99th percentile so the lit surfaces get the colours (brighter cells take the top colour).
  if (scalar != DisplayScalar::Area && values.size() > 100) {
    std::vector<double> sorted(values);
    const size_t k = static_cast<size_t>(0.99 * (sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    if (sorted[k] > lo) hi = sorted[k];
  }
  // ParaView's default "Cool to Warm" diverging map (Moreland 2009).
  auto ctf = vtkSmartPointer<vtkColorTransferFunction>::New();
  ctf->SetColorSpaceToDiverging();
  ctf->AddRGBPoint(lo, 0.230, 0.299, 0.754);
  ctf->AddRGBPoint(hi, 0.706, 0.016, 0.150);
  ctf->Build();
  return ctf;
}

}  // namespace rad
