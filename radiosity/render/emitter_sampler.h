#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/lighting/power_distribution.h"
#include "radiosity/scene/scene.h"

namespace rad {

// A point on an emitter chosen for next-event estimation.
struct EmitterSample {
  int element = -1;
  Eigen::Vector3d position, normal;
  Rgb radiance;        // Ke of the element (emitted from the front only)
  double pdfArea = 0;  // probability density per unit area of choosing this point
};

// Picks emitter elements with probability proportional to their power (emitterPower: area ×
// Ke summed over the channels, lighting/power_distribution.h), then a uniform point on the chosen
// triangle: bright, large emitters get the samples, and the density per area is the same on every
// element of a uniform light.
class EmitterSampler {
 public:
  EmitterSampler(const Scene& scene, const PatchMesh& mesh);
  bool empty() const { return elements_.empty(); }
  int count() const { return static_cast<int>(elements_.size()); }
  // u0 picks the element, (u1, u2) the point on it.
  EmitterSample sample(double u0, double u1, double u2) const;
  // The same from one 2D point: u picks the element and, rescaled to [0,1) within the element's
  // share, goes on to pick the point with v, so a stratified (u, v) set stays stratified over
  // the emitters' whole area rather than only within each element.
  EmitterSample sample(double u, double v) const;
  // Density per unit area with which sample() produces a point on `element` (0 for non-emitters).
  double pdfArea(int element) const { return pdfArea_[element]; }

 private:
  EmitterSample pointOn(size_t k, double u1, double u2) const;  // on elements_[k]

  std::vector<int> elements_;
  // Per emitter element, copied from the mesh once: reading them through its half-edge
  // structure at every sample was a visible share of a render.
  std::vector<std::array<Eigen::Vector3d, 3>> corners_;
  std::vector<Eigen::Vector3d> normals_;
  PowerDistribution power_;      // over elements_
  std::vector<double> pdfArea_;  // per mesh element
  std::vector<Rgb> radiance_;    // per mesh element
};

}  // namespace rad
