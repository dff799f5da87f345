#include "radiosity/render/distribution_ray_tracer.h"

#include <cmath>
#include <vector>

#include "radiosity/core/log.h"
#include "radiosity/render/glossy_lobe.h"
#include "radiosity/render/scattering.h"

namespace rad {
namespace {

double powerHeuristic(double pdfA, double pdfB) {
  const double a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0 ? a / (a + b) : 0.0;
}

}  // namespace

DistributionRayTracer::DistributionRayTracer(const RenderScene& scene, DistributionOptions options)
    : scene_(scene), options_(options) {
  for (const Material& m : scene.scene().materials)
    if (GlossyLobe::applies(m) && (m.diffuse + m.specular).maxComponent() > 1)
      logWarning(m.sourceFile + ":" + std::to_string(m.sourceLine) + ": material '" + m.name +
                 "': Kd + Ks > 1 reflects more light than it receives (glossy lobe)");
}

Rgb DistributionRayTracer::radiance(const Eigen::Vector3d& startOrigin,
                                    const Eigen::Vector3d& startDirection, Rng& rng,
                                    RayCounts& counts) const {
  const EmitterSampler& lights = scene_.emitters();
  const double time = scene_.hasMotion() ? rng.uniform() : 0.0;  // one moment per camera sample
  Eigen::Vector3d origin = startOrigin, direction = startDirection;
  Rgb result, throughput = Rgb::all(1.0);
  double lobePdf = 0;  // 0: the last scattering was a delta (camera, mirror, glass)

  for (int depth = 0;; ++depth) {
    const SurfaceHit hit = scene_.intersect(origin, direction, time);
    ++(depth == 0 ? counts.camera : counts.closest);
    if (!hit.hit()) {  // the sky and the sun's disc, which only the diffuse part samples below
      result += throughput * scene_.lights().escapedRadiance(direction);
      break;
    }
    if (depth > options_.maxDepth) break;
    const Material& m = *hit.material;

    if (m.isSpecular()) {
      if (!continueSpecular(scene_, hit, origin, direction, throughput,
                            [&] { return rng.uniform(); }))
        break;
      lobePdf = 0;
      continue;
    }
    if (!hit.front) break;  // back faces are black, as in every method

    if (m.isEmitter()) {
      if (lobePdf == 0) {
        result += throughput * m.emission;
      } else {  // reached through a glossy lobe, which the emitter sample could also have found
        const double cosY = -hit.normal.dot(direction);
        const double lightPdf = lights.pdfArea(hit.element) * hit.distance * hit.distance / cosY;
        result += throughput * m.emission * powerHeuristic(lobePdf, lightPdf);
      }
    }
    const bool isGlossy = GlossyLobe::applies(m);
    const GlossyLobe glossy(m);  // used only when isGlossy
    if (hit.diffuse.maxComponent() == 0 && !isGlossy) break;
    const Eigen::Vector3d mirror = reflect(direction, hit.normal);

    // Soft shadow: one point on the area emitters. The diffuse part has no other strategy; the
    // glossy part is weighed against the lobe sample below.
    const EmitterSample s = lights.sample(rng.uniform(), rng.uniform(), rng.uniform());
    if (s.element >= 0 && s.element != hit.element) {
      Eigen::Vector3d w = s.position - hit.position;
      const double d2 = w.squaredNorm();
      w /= std::sqrt(d2);
      const double cosX = hit.normal.dot(w), cosY = -s.normal.dot(w);
      if (cosX > 0 && cosY > 0) {
        ++counts.shadow;
        if (!scene_.occluded(scene_.spawn(hit, w), s.position, time)) {
          const double lightPdf = s.pdfArea * d2 / cosY;
          Rgb f = hit.diffuse * (1.0 / M_PI);
          if (isGlossy)
            f += glossy.brdf(w, mirror) * powerHeuristic(lightPdf, glossy.pdf(w, mirror));
          result += throughput * f * s.radiance * (cosX / lightPdf);
        }
      }
    }

    // The point, spot and directional lights and the sky (scene_lights.h): the delta lights
    // through both lobes (no scattered ray can find them), the sun's disc and the sky for the
    // diffuse part only, which has no other strategy (the glossy lobe's rays see them).
    const SceneLights& sceneLights = scene_.lights();
    if (!sceneLights.empty()) {
      thread_local std::vector<SceneLights::Arrival> arrivals;
      sceneLights.deltaArrivals(scene_, hit, counts, time, arrivals);
      for (const SceneLights::Arrival& a : arrivals) {
        Rgb f = hit.diffuse * (1.0 / M_PI);
        if (isGlossy) f += glossy.brdf(a.direction, mirror);
        result += throughput * f * a.irradiance;
      }
      if (hit.diffuse.maxComponent() > 0)
        for (int k = 0; k < sceneLights.areaCount(); ++k)
          result += throughput * hit.diffuse *
                    (sceneLights.sampleArea(k, scene_, hit, {rng.uniform(), rng.uniform()}, counts,
                                            0, time) /
                     M_PI);
    }

    if (!isGlossy) break;  // a diffuse surface ends the path: no diffuse interreflection
    // Glossy reflection: f_g·cosθ/pdf = Ks·(n+2)/(n+1)·cosθ.
    const Eigen::Vector3d w = glossy.sample(mirror, rng.uniform(), rng.uniform());
    const double cosX = hit.normal.dot(w);
    if (cosX <= 0) break;  // the lobe dips below the surface: no light from there
    throughput = throughput * glossy.ks * ((glossy.exponent + 2) / (glossy.exponent + 1) * cosX);
    lobePdf = glossy.pdf(w, mirror);
    origin = scene_.spawn(hit, w);
    direction = w;
    if (!(lobePdf > 0) || throughput.maxComponent() == 0) break;
  }
  return result;
}

}  // namespace rad
