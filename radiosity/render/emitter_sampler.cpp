#include "radiosity/render/emitter_sampler.h"

#include <algorithm>
#include <cmath>

namespace rad {

EmitterSampler::EmitterSampler(const Scene& scene, const PatchMesh& mesh)
    : pdfArea_(mesh.elementCount(), 0.0), radiance_(mesh.elementCount()) {
  double total = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Rgb ke = scene.materials[mesh.material(e)].emission;
    radiance_[e] = ke;
    const double power = mesh.area(e) * ke.sum();
    if (!(power > 0)) continue;
    elements_.push_back(e);
    corners_.push_back(mesh.corners(e));
    normals_.push_back(mesh.normal(e));
    total += power;
    cdf_.push_back(total);
  }
  for (size_t k = 0; k < elements_.size(); ++k) {
    cdf_[k] /= total;
    const int e = elements_[k];
    pdfArea_[e] = radiance_[e].sum() / total;  // (A·Ke/total) · (1/A)
  }
  if (!cdf_.empty()) cdf_.back() = 1.0;
}

EmitterSample EmitterSampler::sample(double u, double v) const {
  if (elements_.empty()) return {};
  const size_t k = std::min<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin(),
                                    elements_.size() - 1);
  const double low = k > 0 ? cdf_[k - 1] : 0.0, width = cdf_[k] - low;
  const double rescaled =
      width > 0 ? std::clamp((u - low) / width, 0.0, std::nextafter(1.0, 0.0)) : 0.5;
  return pointOn(k, rescaled, v);
}

EmitterSample EmitterSampler::sample(double u0, double u1, double u2) const {
  if (elements_.empty()) return {};
  const size_t k = std::min<size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u0) - cdf_.begin(),
                                    elements_.size() - 1);
  return pointOn(k, u1, u2);
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
