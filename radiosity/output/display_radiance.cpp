#include "radiosity/output/display_radiance.h"

#include <cmath>

namespace rad {

std::vector<Rgb> radianceFromRadiosity(const std::vector<Rgb>& radiosity) {
  std::vector<Rgb> radiance(radiosity.size());
  for (size_t e = 0; e < radiosity.size(); ++e) radiance[e] = radiosity[e] / M_PI;
  return radiance;
}

ToneMap solutionToneMap(const std::vector<Rgb>& radiosity, const std::vector<double>& area) {
  return ToneMap::autoExposure(radianceFromRadiosity(radiosity), area);
}

}  // namespace rad
