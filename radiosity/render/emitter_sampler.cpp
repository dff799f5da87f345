#include "radiosity/render/emitter_sampler.h"

#include <algorithm>
#include <cmath>

namespace rad {

EmitterSampler::EmitterSampler(const Scene& scene, const PatchMesh& mesh)
    : pdfArea_(mesh.elementCount(), 0.0), radiance_(mesh.elementCount()) {
  std::vector<double> powers;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Rgb ke = scene.materials[mesh.material(e)].emission;
    radiance_[e] = ke;
    const double power = emitterPower(mesh.area(e), ke);
    if (!(power > 0)) continue;
    elements_.push_back(e);
    corners_.push_back(mesh.corners(e));
    normals_.push_back(mesh.normal(e));
    powers.push_back(power);
  }
  power_ = PowerDistribution(powers);
  for (const int e : elements_)
    pdfArea_[e] = emitterPowerPerArea(radiance_[e]) / power_.total();  // (A·Ke/total) · (1/A)
}

EmitterSample EmitterSampler::sample(double u, double v) const {
  if (elements_.empty()) return {};
  const size_t k = power_.pick(u);
  return pointOn(k, power_.rescaled(u, k), v);
}

EmitterSample EmitterSampler::sample(double u0, double u1, double u2) const {
  if (elements_.empty()) return {};
  return pointOn(power_.pick(u0), u1, u2);
}

EmitterSample EmitterSampler::pointOn(size_t k, double u1, double u2) const {
  EmitterSample s;
  s.element = elements_[k];
  const auto& c = corners_[k];
  // Uniform point on a triangle (square-root warp).
  const double r = std::sqrt(u1);
  s.position = (1 - r) * c[0] + r * (1 - u2) * c[1] + r * u2 * c[2];
  s.normal = normals_[k];
  s.radiance = radiance_[s.element];
  s.pdfArea = pdfArea_[s.element];
  return s;
}

}  // namespace rad
