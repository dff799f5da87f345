#include "radiosity/render/path_tracer.h"

#include <cmath>

#include "radiosity/render/scattering.h"

namespace rad {
namespace {

double powerHeuristic(double pdfA, double pdfB) {
  const double a = pdfA * pdfA, b = pdfB * pdfB;
  return a / (a + b);
}

}  // namespace

PathTracer::PathTracer(const RenderScene& scene, PathTracerOptions options)
    : scene_(scene), options_(options) {}

Rgb PathTracer::trace(const Eigen::Vector3d& startOrigin, const Eigen::Vector3d& startDirection,
                      Sampler& sampler, RayCounts& counts, const PathBinning* binning, Rgb* binned,
                      SplatImage* /*splats*/) const {
  const EmitterSampler& lights = scene_.emitters();
  const SceneLights& sceneLights = scene_.lights();
  Eigen::Vector3d origin = startOrigin, direction = startDirection;
  Rgb result, throughput = Rgb::all(1.0);
  bool specularBefore = true;    // the camera (or a mirror) cannot sample emitters itself
  double bsdfPdf = 0;            // solid-angle density of the last diffuse bounce
  Eigen::Vector3d bounceNormal;  // the normal at the last diffuse bounce
  int diffuseBounces = 0, specularRun = 0;
  bool first = true;
  // With a binning: the eye path's vertex labels so far (eye to light) and a scratch label.
  std::string eyeVertices, label;
  auto add = [&](const Rgb& c, std::string_view lightSide) {
    result += c;
    if (!binning) return;
    lightToEyeLabel(label, lightSide, eyeVertices);
    const int bin = binning->binOf(label);
    if (bin >= 0) binned[bin] += c;
  };

  for (;;) {
    const SurfaceHit hit = scene_.intersect(origin, direction);
    ++(first ? counts.camera : counts.closest);
    first = false;
    if (!hit.hit()) {
      // Out of the scene: the sky and the sun, of which NEE took its share after a diffuse bounce.
      if (!sceneLights.empty())
        add(throughput * (specularBefore ? sceneLights.escapedRadiance(direction)
                                         : sceneLights.escapedRadiance(direction, bounceNormal, 1)),
            {});
      break;
    }
    const Material& m = *hit.material;

    if (m.isSpecular()) {
      if (!continueSpecular(scene_, hit, origin, direction, throughput,
                            [&] { return sampler.get1D(); }))
        break;
      if (binning) eyeVertices.push_back('S');
      specularBefore = true;
      if (++specularRun > kSpecularRouletteAfter && !survivesRoulette(throughput, sampler.get1D()))
        break;
      continue;
    }
    specularRun = 0;
    if (!hit.front) break;  // back faces are black, as in the radiosity pass

    if (m.isEmitter()) {
      if (specularBefore) {
        add(throughput * m.emission, {});
      } else {
        // The light could have been sampled here by NEE too: weigh by MIS.
        const double cosY = -hit.normal.dot(direction);
        const double lightPdf = lights.pdfArea(hit.element) * hit.distance * hit.distance / cosY;
        add(throughput * m.emission * powerHeuristic(bsdfPdf, lightPdf), {});
      }
    }
    const Rgb rho = hit.diffuse;
    if (rho.maxComponent() == 0) break;
    if (binning) eyeVertices.push_back('D');

    // Next-event estimation: one point on an emitter, weighed against the cosine bounce.
    const Point2 lightPoint = sampler.get2D();
    const EmitterSample s = lights.sample(lightPoint.x, lightPoint.y);
    if (s.element >= 0 && s.element != hit.element) {
      Eigen::Vector3d w = s.position - hit.position;
      const double d2 = w.squaredNorm();
      w /= std::sqrt(d2);
      const double cosX = hit.normal.dot(w), cosY = -s.normal.dot(w);
      if (cosX > 0 && cosY > 0) {
        ++counts.shadow;
        if (!scene_.occluded(scene_.spawn(hit, w), s.position)) {
          const double lightPdf = s.pdfArea * d2 / cosY;
          const double weight = powerHeuristic(lightPdf, cosX / M_PI);
          add(throughput * rho * s.radiance * (cosX / M_PI / lightPdf * weight), {});
        }
      }
    }

    // Next-event estimation to the point, spot, directional and sky lights (scene_lights.h).
    if (!sceneLights.empty())
      add(throughput * rho *
              (sceneLights.sampleIrradiance(scene_, hit, sampler, counts, 1) * (1.0 / M_PI)),
          {});

    // Cosine-weighted bounce: f·cos/pdf = ρ.
    const Point2 bounce = sampler.get2D();
    direction = cosineDirection(hit.normal, bounce.x, bounce.y);
    bsdfPdf = hit.normal.dot(direction) / M_PI;
    if (!(bsdfPdf > 0)) break;
    bounceNormal = hit.normal;
    origin = scene_.spawn(hit, direction);
    throughput = throughput * rho;
    specularBefore = false;
    if (++diffuseBounces >= options_.rouletteAfter &&
        !survivesRoulette(throughput, sampler.get1D()))
      break;
  }
  return result;
}

}  // namespace rad
