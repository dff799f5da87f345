#include "radiosity/output/elements_csv.h"

#include <cmath>
#include <ios>
#include <limits>
#include <string>

#include "radiosity/core/check.h"

namespace rad {

void writeElementsCsv(std::ostream& out, const PatchMesh& mesh, const std::vector<Rgb>& radiosity) {
  const int count = mesh.elementCount();
  RAD_CHECK_EQ(radiosity.size(), count);

  // Save and restore the caller's formatting: the stream may be shared with other writers.
  const std::ios_base::fmtflags flags = out.flags();
  const std::streamsize precision = out.precision();
  out.unsetf(std::ios_base::floatfield);  // %g style: shortest of fixed/scientific at 17 digits
  out.precision(std::numeric_limits<double>::max_digits10);

  out << "element,patch,material,area,cx,cy,cz,nx,ny,nz,B_r,B_g,B_b,L_r,L_g,L_b\n";
  for (int e = 0; e < count; ++e) {
    const Eigen::Vector3d c = mesh.centroid(e);
    const Eigen::Vector3d n = mesh.normal(e);
    const Rgb& b = radiosity[e];
    const Rgb l = b / M_PI;
    out << e << ',' << mesh.patch(e) << ',' << mesh.material(e) << ',' << mesh.area(e) << ','
        << c.x() << ',' << c.y() << ',' << c.z() << ',' << n.x() << ',' << n.y() << ',' << n.z()
        << ',' << b.r << ',' << b.g << ',' << b.b << ',' << l.r << ',' << l.g << ',' << l.b << '\n';
  }

  out.flags(flags);
  out.precision(precision);
}

}  // namespace rad
