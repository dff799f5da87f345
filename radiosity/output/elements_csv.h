#pragma once

#include <ostream>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"

namespace rad {

// Writes one CSV row per element of the solution, for analysis in a spreadsheet or pandas:
//   element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b
// `material` is the scene's material index (names are in summary.json); area in scene units²;
// c = centroid, n = unit front normal; B = radiosity (W·m⁻²) exactly as given; L = B/π, the
// outgoing radiance (W·m⁻²·sr⁻¹) of the Lambertian element. Doubles are written with 17
// significant digits so they read back bit-exact. The stream's formatting state is restored.
// `radiosity` has one entry per element (RAD_CHECK: CheckFailure otherwise).
void writeElementsCsv(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity);

}  // namespace rad
