#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"

namespace rad {

// Writes one CSV row per element of the solution, for analysis in a spreadsheet or pandas:
//   element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b[,Ed_r,Ed_g,Ed_b]
//   [,buried_cells]
// `material` is the scene's material index (names are in summary.json); area in scene units²;
// c = centroid, n = unit front normal; B = radiosity (W·m⁻²) exactly as given; L = B/π, the
// outgoing radiance (W·m⁻²·sr⁻¹) of the Lambertian element. With `directIrradiance` (one per
// element: Solution::directIrradiance), the Ed columns hold E_d, the irradiance (W·m⁻²) the element
// received straight from the emitters and lights, as given. Doubles are written as the shortest
// text that reads back bit-exact (std::to_chars). With `buriedCells` (one per element: the
// solve's ElementExposure masks), the last column holds them in hexadecimal, so that a reuse of
// the solution needs no probe rays. The stream's formatting state is untouched. `radiosity`, and
// each of the optional columns given, has one entry per element (RAD_CHECK: CheckFailure
// otherwise).
void writeElementsCsv(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity,
                      const std::vector<uint64_t>* buriedCells = nullptr,
                      const std::vector<Rgb>* directIrradiance = nullptr);

// The header line writeElementsCsv writes first (without its newline), the three columns it adds
// after it with the direct irradiance, and the column it ends with when it writes the buried
// cells.
inline constexpr const char* kElementsCsvHeader =
    "element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b";
inline constexpr const char* kDirectIrradianceColumns = "Ed_r,Ed_g,Ed_b";
inline constexpr const char* kBuriedCellsColumn = "buried_cells";

// One row of an elements CSV as read back; `line` is its 1-based line in the file.
struct ElementsCsvRow {
  int line = 0;
  int element = 0, patch = 0, material = 0;
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  Rgb radiosity, radiance;  // B (W·m⁻²) and L = B/π (W·m⁻²·sr⁻¹), as written
  // E_d (W·m⁻²), finite and non-negative; 0 in a file without the Ed columns
  // (ElementsCsv::hasDirectIrradiance).
  Rgb directIrradiance;
  // Bit 8y + x set: cell (x, y) of the element's 8×8 exposure grid is buried (ElementExposure).
  // 0 in a file without the column (ElementsCsv::hasBuriedCells).
  uint64_t buriedCells = 0;
};

struct ElementsCsv {
  std::vector<ElementsCsvRow> rows;
  bool hasDirectIrradiance = false;  // the file has the Ed_r,Ed_g,Ed_b columns
  bool hasBuriedCells = false;       // the file has the buried_cells column
};

// Reads what writeElementsCsv wrote, row by row in file order (empty lines are skipped), with or
// without the Ed columns and with or without the buried_cells column (the four headers the writer
// writes). Throws InputError naming `source` (or `path`) and the line for a missing or different
// header, a row without exactly the header's number of comma-separated fields, a field that is not
// a finite number, an element, patch or material index that is not a non-negative integer, a
// negative direct irradiance, or buried cells that are not 1 to 16 hexadecimal digits; a file that
// cannot be opened is an InputError naming it. It checks the format only: what the rows must
// describe (element order, centroids, counts) is the caller's to check.
ElementsCsv readElementsCsv(std::istream& in, const std::string& source);
ElementsCsv readElementsCsv(const std::string& path);

}  // namespace rad
