#include "radiosity/formfactors/specular_paths.h"

#include <cmath>

#include "radiosity/core/russian_roulette.h"

namespace rad {

SpecularPathEnd traceThroughSpecular(const RayCaster& rays,
                                     const std::vector<Eigen::Vector3d>& normals,
                                     const std::vector<SpecularSurface>& surfaces,
                                     Eigen::Vector3d origin, Eigen::Vector3d direction, int from,
                                     Rng& rng, int* raysCast) {
  SpecularPathEnd end;
  int previous = from;
  for (;;) {
    const RayHit hit = rays.closestHit(origin, direction);
    ++*raysCast;
    if (!hit.hit() || hit.element == previous) return {};
    const int j = hit.element;
    const Eigen::Vector3d& n = normals[j];
    const double cosine = n.dot(direction);  // < 0: the ray meets j's front
    const SpecularSurface& surface = surfaces.empty() ? SpecularSurface{} : surfaces[j];
    if (surface.kind == SpecularSurface::Kind::Diffuse) {
      if (cosine >= 0) return {};  // back faces absorb
      end.element = j;
      end.point = origin + hit.distance * direction;
      return end;
    }
    if (end.specularBounces >= kSpecularBounceLimit) return {};
    if (end.specularBounces >= kSpecularRouletteAfter &&
        !survivesRouletteWithinOne(end.weight, rng.uniform()))
      return {};
    const Eigen::Vector3d point = origin + hit.distance * direction;
    if (surface.kind == SpecularSurface::Kind::Mirror) {
      if (cosine >= 0) return {};  // one-sided mirror
      direction = direction - 2 * cosine * n;
      origin = rays.liftOff(point, n, direction);
      end.weight = end.weight * surface.reflectance;
    } else {
      // Glass, two-sided: entering through the front, leaving through the back.
      const bool entering = cosine < 0;
      const Eigen::Vector3d facing = entering ? n : Eigen::Vector3d(-n);
      const double cosI = std::fabs(cosine);
      const double etaI = entering ? 1.0 : surface.ior, etaT = entering ? surface.ior : 1.0;
      if (rng.uniform() < fresnelDielectric(cosI, etaI, etaT)) {
        direction = direction + 2 * cosI * facing;
      } else {
        const double eta = etaI / etaT;
        const double cosT = std::sqrt(std::max(0.0, 1.0 - eta * eta * (1.0 - cosI * cosI)));
        direction = (eta * direction + (eta * cosI - cosT) * facing).normalized();
        if (entering) end.weight = end.weight * surface.transmittance;
      }
      origin = rays.liftOff(point, n, direction);
    }
    ++end.specularBounces;
    previous = j;
  }
}

}  // namespace rad
