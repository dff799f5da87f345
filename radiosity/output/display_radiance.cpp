#include "radiosity/output/display_radiance.h"

#include <cmath>

#include "radiosity/core/check.h"

namespace rad {

std::vector<Rgb> radianceFromRadiosity(const std::vector<Rgb>& radiosity) {
  std::vector<Rgb> radiance(radiosity.size());
  for (size_t e = 0; e < radiosity.size(); ++e) radiance[e] = radiosity[e] / M_PI;
  return radiance;
}

ToneMap solutionToneMap(const std::vector<Rgb>& radiosity, const std::vector<double>& area,
                        const std::vector<Rgb>& emission) {
  RAD_CHECK_EQ(emission.size(), area.size());
  std::vector<double> lit = area;
  bool anyLit = false;
  for (size_t e = 0; e < lit.size(); ++e) {
    if (emission[e].maxComponent() > 0) lit[e] = 0;
    anyLit = anyLit || lit[e] > 0;
  }
  return ToneMap::autoExposure(radianceFromRadiosity(radiosity), anyLit ? lit : area);
}

}  // namespace rad
