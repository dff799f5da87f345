#include "radiosity/formfactors/hemisphere_form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "radiosity/core/rng.h"
#include "radiosity/formfactors/hemisphere_sampling.h"

namespace rad {

double FormFactorRow::valueFor(int target) const {
  const auto it = std::lower_bound(targets.begin(), targets.end(), target);
  return (it != targets.end() && *it == target) ? values[it - targets.begin()] : 0.0;
}

HemisphereFormFactors::HemisphereFormFactors(const PatchMesh& mesh, const RayCaster& rays,
                                             HemisphereOptions options)
    : mesh_(mesh), rays_(rays), options_(options) {
  if (options_.raysPerElement < 1) throw std::invalid_argument("rays per element must be >= 1");
  if (!options_.rayMultiplier.empty() &&
      options_.rayMultiplier.size() != static_cast<size_t>(mesh.elementCount()))
    throw std::invalid_argument("one ray multiplier per element expected");
  normals_.resize(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) normals_[e] = mesh.normal(e);
}

std::vector<std::array<double, 4>> HemisphereFormFactors::rowSamples(int element) const {
  const int n = raysForRow(element);
  // All random numbers first, serially from the row's own stream: reproducible for any
  // scheduling. A g×g jittered grid stratifies the first g² rays; the rest are plain random.
  Rng rng(streamKey(options_.seed, static_cast<uint64_t>(element)));
  const int g = static_cast<int>(std::sqrt(static_cast<double>(n)));
  const int cells = g * g;
  std::vector<int> positionCell(cells);
  std::iota(positionCell.begin(), positionCell.end(), 0);
  for (int k = cells - 1; k > 0; --k) std::swap(positionCell[k], positionCell[rng.below(k + 1)]);
  std::vector<std::array<double, 4>> samples(n);
  for (int k = 0; k < n; ++k) {
    auto& s = samples[k];
    for (double& u : s) u = rng.uniform();
    if (k < cells) {
      const int p = positionCell[k];
      s[0] = ((k % g) + s[0]) / g;  // direction stratum k
      s[1] = ((k / g) + s[1]) / g;
      s[2] = ((p % g) + s[2]) / g;  // shuffled position stratum
      s[3] = ((p / g) + s[3]) / g;
    }
  }
  return samples;
}

RowRay HemisphereFormFactors::castSample(int element, const std::array<Eigen::Vector3d, 3>& corners,
                                         const std::array<double, 4>& s) const {
  const Eigen::Vector3d& normal = normals_[element];
  RowRay ray;
  ray.direction = Frame(normal).toWorld(cosineWeightedDirection(s[0], s[1]));
  ray.origin = rays_.liftOff(uniformPointOnTriangle(corners, s[2], s[3]), normal, normal);
  const RayHit hit = rays_.closestHit(ray.origin, ray.direction);
  ray.distance = hit.distance;
  // Only the front of a surface receives: a back-face hit is absorbed and counts as escaped.
  if (hit.hit() && hit.element != element && normals_[hit.element].dot(ray.direction) < 0)
    ray.target = hit.element;
  return ray;
}

std::vector<RowRay> HemisphereFormFactors::traceRow(int element) const {
  const auto samples = rowSamples(element);
  const auto corners = mesh_.corners(element);
  std::vector<RowRay> rays(samples.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, samples.size(), 64),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k != range.end(); ++k)
                        rays[k] = castSample(element, corners, samples[k]);
                    });
  return rays;
}

FormFactorRow HemisphereFormFactors::computeRow(int element) const {
  const auto samples = rowSamples(element);
  const int n = static_cast<int>(samples.size());
  const auto corners = mesh_.corners(element);
  const Eigen::Vector3d& normal = normals_[element];
  std::vector<int> firstHit(n, -1);
  const bool extended = !options_.specular.empty();
  std::vector<Rgb> weight(extended ? n : 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 64), [&](const tbb::blocked_range<int>& range) {
    for (int k = range.begin(); k != range.end(); ++k) {
      if (!extended) {
        firstHit[k] = castSample(element, corners, samples[k]).target;
        continue;
      }
      const auto& s = samples[k];
      const Eigen::Vector3d direction = Frame(normal).toWorld(cosineWeightedDirection(s[0], s[1]));
      const Eigen::Vector3d origin = rays_.liftOff(uniformPointOnTriangle(corners, s[2], s[3]), normal, normal);
      // Fresnel choices draw from the ray's own stream: reproducible on any thread count.
      Rng pathRng(streamKey(options_.seed, static_cast<uint64_t>(element), static_cast<uint64_t>(k) + 1));
      int rays = 0;
      const SpecularPathEnd end = traceThroughSpecular(rays_, normals_, options_.specular, origin, direction,
                                                       element, pathRng, options_.maxSpecularDepth, &rays);
      if (end.element >= 0 && end.element != element) {
        firstHit[k] = end.element;
        weight[k] = end.weight;
      }
      extraRays_ += rays - 1;
    }
  });

  // Group rays by target (sorting a permutation keeps each ray's weight with it).
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return firstHit[a] < firstHit[b]; });
  FormFactorRow row;
  const double perRay = 1.0 / n;
  size_t k = 0;
  while (k < order.size() && firstHit[order[k]] < 0) ++k;
  row.escaped = k * perRay;
  bool anyTint = false;
  while (k < order.size()) {
    const int target = firstHit[order[k]];
    size_t end = k;
    Rgb tint;
    while (end < order.size() && firstHit[order[end]] == target) {
      if (extended) tint += weight[order[end]] * perRay;
      ++end;
    }
    row.targets.push_back(target);
    row.values.push_back((end - k) * perRay);
    if (extended) {
      anyTint |= !(tint.r == tint.g && tint.g == tint.b && tint.r == row.values.back());
      row.tinted.push_back(tint);
    }
    k = end;
  }
  if (!anyTint) row.tinted.clear();  // every path was untinted: a plain row
  return row;
}

}  // namespace rad
