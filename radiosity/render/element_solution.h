#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/render/sobol_sampler.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// A radiosity solution per element as the eye passes over it read it (InterpolatedPreview,
// DirectIndirectSplit, FinalGather), with the materials' emission and reflectance (their
// textures' averages, as solved).
struct ElementSolution {
  // `radiosity`: B per element (W/m²); emission E = π·Ke comes from the materials.
  ElementSolution(const RenderScene& scene, const std::vector<Rgb>& radiosity);

  std::vector<Rgb> radiance;   // B/π per element
  std::vector<Rgb> reflected;  // (B − E)/π per element, at least 0
  std::vector<Rgb> emitted;    // Le per element (its texture's average)
  std::vector<Rgb> rho;        // reflectance per element (its texture's average), as solved
};

// Per element its exposed area (element_exposure.h): the weights of the vertex values.
std::vector<double> exposedAreas(const PatchMesh& mesh, const ElementExposure& exposure);

// Per-element colours as the vertex interpolation takes them.
std::vector<Eigen::Vector3d> asVectors(const std::vector<Rgb>& perElement);

// Calls fn(hit, k) at each of `points` Sobol points k (stream `key`) of element e that lies in its
// exposed part (element_exposure.h), `hit` placed there, facing out of the element's front; the
// number of such points. The solution's B is over the exposed part: so are the means over it.
template <class Fn>
int forEachExposedPoint(const RenderScene& scene, const ElementExposure& exposure, int e,
                        int points, uint64_t key, Fn&& fn) {
  const PatchMesh& mesh = scene.mesh();
  const auto c = mesh.corners(e);
  SurfaceHit hit;
  hit.element = e;
  hit.normal = mesh.normal(e);
  hit.front = true;
  hit.material = &scene.material(e);
  int exposed = 0;
  for (int k = 0; k < points; ++k) {
    const Point2 p = SobolSampler::point(k, streamKey(key, e, 1));
    if (exposure.buried(e, p.x, p.y)) continue;
    ++exposed;
    const double r = std::sqrt(p.x);
    hit.position = (1 - r) * c[0] + r * (1 - p.y) * c[1] + r * p.y * c[2];
    fn(static_cast<const SurfaceHit&>(hit), k);
  }
  return exposed;
}

}  // namespace rad
