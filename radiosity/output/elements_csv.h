#pragma once

#include <Eigen/Core>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"

namespace rad {

// Writes one CSV row per element of the solution, for analysis in a spreadsheet or pandas:
//   element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b
// `material` is the scene's material index (names are in summary.json); area in scene units²;
// c = centroid, n = unit front normal; B = radiosity (W·m⁻²) exactly as given; L = B/π, the
// outgoing radiance (W·m⁻²·sr⁻¹) of the Lambertian element. Doubles are written as the shortest
// text that reads back bit-exact (std::to_chars). The stream's formatting state is untouched.
// `radiosity` has one entry per element (RAD_CHECK: CheckFailure otherwise).
void writeElementsCsv(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity);

// The header line writeElementsCsv writes first (without its newline).
inline constexpr const char* kElementsCsvHeader =
    "element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b";

// One row of an elements CSV as read back; `line` is its 1-based line in the file.
struct ElementsCsvRow {
  int line = 0;
  int element = 0, patch = 0, material = 0;
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  Rgb radiosity, radiance;  // B (W·m⁻²) and L = B/π (W·m⁻²·sr⁻¹), as written
};

// Reads what writeElementsCsv wrote, row by row in file order (empty lines are skipped). Throws
// InputError naming `source` (or `path`) and the line for a missing or different header, a row
// without exactly 16 comma-separated fields, a field that is not a finite number, or an element,
// patch or material index that is not a non-negative integer; a file that cannot be opened is
// an InputError naming it. It checks the format only: what the rows must describe (element
// order, centroids, counts) is the caller's to check.
std::vector<ElementsCsvRow> readElementsCsv(std::istream& in, const std::string& source);
std::vector<ElementsCsvRow> readElementsCsv(const std::string& path);

}  // namespace rad
