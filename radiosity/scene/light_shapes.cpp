#include "radiosity/scene/light_shapes.h"

#include <algorithm>
#include <cmath>

namespace rad {

double spotFalloff(const Light& light, double cosAngle) {
  if (cosAngle < light.cosOuter) return 0;
  if (cosAngle >= light.cosInner) return 1;
  const double t = (cosAngle - light.cosOuter) / (light.cosInner - light.cosOuter);
  return t * t * (3 - 2 * t);
}

double sunCosHalfAngle(const Light& light) {
  return std::cos(0.5 * light.angularDiameterDegrees * M_PI / 180);
}

double sunSolidAngle(const Light& light) { return 2 * M_PI * (1 - sunCosHalfAngle(light)); }

Rgb sunRadiance(const Light& light) {
  const double c = sunCosHalfAngle(light);
  const double sin2 = (1 - c) * (1 + c);  // sin²h without the cancellation of 1 − c²
  return sin2 > 0 ? light.irradiance / (M_PI * sin2) : Rgb();
}

Eigen::Vector3d sunDirection(const Light& light, double u1, double u2) {
  const Eigen::Vector3d axis = -light.direction;
  if (light.angularDiameterDegrees <= 0) return axis;
  // Orthonormal basis around the axis (Duff et al., JCGT 2017).
  const double sign = std::copysign(1.0, axis.z());
  const double a = -1.0 / (sign + axis.z()), b = axis.x() * axis.y() * a;
  const Eigen::Vector3d t(1 + sign * axis.x() * axis.x() * a, sign * b, -sign * axis.x());
  const Eigen::Vector3d s(b, sign + axis.y() * axis.y() * a, -axis.y());
  const double cosA = 1 - u1 * (1 - sunCosHalfAngle(light));
  const double sinA = std::sqrt(std::max(0.0, 1 - cosA * cosA));
  const double phi = 2 * M_PI * u2;
  return (sinA * std::cos(phi) * t + sinA * std::sin(phi) * s + cosA * axis).normalized();
}

bool insideSunDisc(const Light& light, const Eigen::Vector3d& direction) {
  return light.angularDiameterDegrees > 0 &&
         direction.dot(-light.direction) >= sunCosHalfAngle(light);
}

double cieClearSkyRatio(const Eigen::Vector3d& direction, const Eigen::Vector3d& toSun,
                        const Eigen::Vector3d& up) {
  const double cosTheta = direction.dot(up);
  if (!(cosTheta > 0)) return 0;
  const auto indicatrix = [](double cosAngle) {
    const double c = std::clamp(cosAngle, -1.0, 1.0);
    return 0.91 + 10 * std::exp(-3 * std::acos(c)) + 0.45 * c * c;
  };
  const double gradation = 1 - std::exp(-0.32 / cosTheta);
  return indicatrix(direction.dot(toSun)) * gradation /
         (indicatrix(toSun.dot(up)) * (1 - std::exp(-0.32)));
}

Rgb skyRadiance(const Light& light, const Eigen::Vector3d& direction) {
  if (light.type == LightType::Environment) return light.map->radiance(direction);
  const double cosZenith = direction.dot(light.up);
  if (!(cosZenith > 0)) return {};
  switch (light.skyModel) {
    case SkyModel::Uniform:
      break;
    case SkyModel::CieOvercast:
      return light.radiance * ((1 + 2 * cosZenith) / 3);
    case SkyModel::CieClear:
      return light.radiance * cieClearSkyRatio(direction, -light.direction, light.up);
  }
  return light.radiance;
}

Rgb skyIrradiance(const Light& light, const Eigen::Vector3d& n) {
  if (light.map) return light.map->irradiance(n);
  const double cosA = std::clamp(n.dot(light.up), -1.0, 1.0);
  const double uniform = M_PI * (1 + cosA) / 2;  // ∫ cos over the lune
  if (light.skyModel == SkyModel::Uniform) return light.radiance * uniform;
  // ∫ cosθ_zenith · cos over the lune, in coordinates about the axis up × n: (2/3)(sin α +
  // (π − α) cos α).
  const double a = std::acos(cosA);
  const double zenithWeighted = 2.0 / 3 * (std::sin(a) + (M_PI - a) * cosA);
  return light.radiance * ((uniform + 2 * zenithWeighted) / 3);
}

}  // namespace rad
