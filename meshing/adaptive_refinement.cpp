#include "meshing/adaptive_refinement.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "meshing/vertex_interpolation.h"

namespace rad {
namespace {

// Corner values as displayed: VertexInterpolation's per-vertex means of the luminance.
std::vector<std::array<double, 3>> cornerValues(const PatchMesh& mesh, const std::vector<double>& luminance) {
  const VertexInterpolation interpolation(mesh);
  std::vector<Eigen::Vector3d> perElement(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) perElement[e] = Eigen::Vector3d(luminance[e], 0, 0);
  const std::vector<Eigen::Vector3d> atVertices = interpolation.interpolate(perElement);
  std::vector<std::array<double, 3>> corners(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 3; ++k) corners[e][k] = atVertices[interpolation.triangle(e)[k]].x();
  return corners;
}

}  // namespace

std::vector<double> displayedVariation(const PatchMesh& mesh, const std::vector<double>& luminance) {
  const auto corners = cornerValues(mesh, luminance);
  std::vector<double> variation(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    variation[e] = std::fabs((corners[e][0] + corners[e][1] + corners[e][2]) / 3 - luminance[e]);
  }
  return variation;
}

std::vector<int> selectForRefinement(const PatchMesh& mesh, const std::vector<double>& luminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options) {
  const int n = mesh.elementCount();
  double mean = 0, area = 0;
  for (int e = 0; e < n; ++e) {
    mean += luminance[e] * mesh.area(e);
    area += mesh.area(e);
  }
  mean = area > 0 ? mean / area : 0;
  const double noise = 1e-3 * mean;

  const auto corners = cornerValues(mesh, luminance);
  std::vector<int> selected;
  std::vector<double> priority(n, 0.0);
  for (int e = 0; e < n; ++e) {
    if (mesh.area(e) <= options.minArea) continue;
    const double defect = std::fabs((corners[e][0] + corners[e][1] + corners[e][2]) / 3 - luminance[e]);
    double local = luminance[e], spread = 0;
    for (double c : corners[e]) {
      local = std::max(local, c);
      spread = std::max(spread, std::fabs(c - luminance[e]));
    }
    // A shadow edge inside the element is a jump the element's mean hides (the mean can sit
    // between its corners' values): count it at the spread of the displayed values instead.
    const bool shadowEdge = !partlyShadowed.empty() && partlyShadowed[e];
    const double error = shadowEdge ? std::max(defect, spread) : defect;
    if (error <= noise) continue;
    if (error > options.threshold * local || shadowEdge) {
      selected.push_back(e);
      priority[e] = mesh.area(e) * error * error;
    }
  }
  // Largest share of the displayed error first; ties (equal priority) by index, so the order
  // does not depend on the sort's implementation.
  std::stable_sort(selected.begin(), selected.end(), [&](int a, int b) { return priority[a] > priority[b]; });
  return selected;
}

std::vector<int> refineElements(PatchMesh& mesh, const std::vector<int>& selected,
                                const RefinementOptions& options, int targetElements) {
  const int before = mesh.elementCount();
  const int limit = options.maxElements > 0 ? std::min(targetElements, options.maxElements) : targetElements;
  // Corners and areas of every element before, to find the ones a split changed.
  std::vector<std::array<int, 3>> corners(before);
  std::vector<double> areaBefore(before);
  for (int e = 0; e < before; ++e) {
    corners[e] = mesh.cornerVertices(e);
    areaBefore[e] = mesh.area(e);
  }
  for (int e : selected) {
    if (mesh.elementCount() >= limit) break;
    // A split propagating from an earlier one (Rivara's path) may already have halved e: that
    // already is the refinement e asked for.
    if (mesh.area(e) > options.minArea && mesh.area(e) > 0.75 * areaBefore[e]) mesh.bisect(e);
  }
  std::vector<int> changed;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (e >= before || mesh.cornerVertices(e) != corners[e]) changed.push_back(e);
  return changed;
}

int refinementTarget(int start, int budget, int pass, int passes) {
  if (passes <= 0 || budget <= start) return std::max(start, budget);
  const double fraction = std::min(1.0, static_cast<double>(pass + 1) / passes);
  return static_cast<int>(std::lround(start * std::pow(static_cast<double>(budget) / start, fraction)));
}

}  // namespace rad
