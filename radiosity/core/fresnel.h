#pragma once

#include <algorithm>
#include <cmath>

namespace rad {

// Unpolarised Fresnel reflectance of a dielectric interface, light going from index etaI to
// etaT with incidence cosine cosThetaI >= 0; 1 under total internal reflection. Shared by the
// radiosity pass (extended form factors) and the eye passes.
inline double fresnelDielectric(double cosThetaI, double etaI, double etaT) {
  const double sinT = etaI / etaT * std::sqrt(std::max(0.0, 1 - cosThetaI * cosThetaI));
  if (sinT >= 1) return 1;
  const double cosT = std::sqrt(std::max(0.0, 1 - sinT * sinT));
  const double rs = (etaI * cosThetaI - etaT * cosT) / (etaI * cosThetaI + etaT * cosT);
  const double rp = (etaT * cosThetaI - etaI * cosT) / (etaT * cosThetaI + etaI * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

}  // namespace rad
