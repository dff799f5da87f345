// libFuzzer target: a saved solution (solution.vtp) as `radiosity view DIR` reads it back:
// readSolutionVtp (the check of the writer's layout, VTK's XML reader on what passes it, then the
// array and value checks), then everything the
// viewer computes from the file before it draws: the tone map, the scene name, the per-cell
// values of every --scalar, their colour maps, and the smooth per-point averages.
// Findings: crashes, sanitizer reports, any exception other than InputError, or an accepted
// file giving non-finite cell values or not one value per cell / point.
#include <vtkObject.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "radiosity/core/errors.h"
#include "tests/fuzz/fuzz_temp_dir.h"
#include "viewer/display_scalars.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_vtp.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_solution_vtp: invariant violated: %s\n", what);
  std::abort();
}

bool allFinite(const std::vector<double>& values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // VTK reports every malformed element on stderr; readSolutionVtp turns them into InputError.
  static const bool quiet = (vtkObject::GlobalWarningDisplayOff(), true);
  (void)quiet;
  const std::string path =
      rad::fuzz::writeTemp("solution.vtp", reinterpret_cast<const char*>(data), size);
  vtkSmartPointer<vtkPolyData> solution;
  try {
    solution = rad::readSolutionVtp(path);
  } catch (const rad::InputError& e) {
    check(e.what()[0] != '\0', "an InputError without a message");
    return 0;
  }
  const rad::ToneMap toneMap = rad::solutionToneMap(solution);
  check(std::isfinite(toneMap.exposure) && toneMap.exposure > 0, "a tone map without exposure");
  (void)rad::solutionSceneFile(solution);
  for (int s = 0; s < rad::displayScalarCount; ++s) {
    const auto scalar = static_cast<rad::DisplayScalar>(s);
    const std::vector<double> cells = rad::cellScalars(solution, scalar);
    check(static_cast<vtkIdType>(cells.size()) == solution->GetNumberOfCells(),
          "not one scalar per cell");
    check(allFinite(cells), "a non-finite cell scalar from an accepted file");
    (void)rad::scalarColours(scalar, cells, toneMap);
    if (!rad::displayScalarInfo(scalar).smoothable) continue;
    const std::vector<double> points = rad::pointAverages(solution, cells);
    check(static_cast<vtkIdType>(points.size()) == solution->GetNumberOfPoints(),
          "not one average per point");
  }
  return 0;
}
