#include "meshing/adaptive_refinement.h"

#include <algorithm>
#include <cmath>

namespace rad {

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
  const double floor = 1e-3 * mean;
  const double cosCrease = std::cos(30.0 * M_PI / 180.0);

  std::vector<char> marked(n, 0);
  const TriMesh& m = mesh.mesh();
  for (int e = 0; e < n; ++e) {
    if (!partlyShadowed.empty() && partlyShadowed[e]) marked[e] = 1;
    const Eigen::Vector3d normal = mesh.normal(e);
    for (auto neighbour : m.ff_range(PatchMesh::face(e))) {
      const int f = neighbour.idx();
      if (f < e || mesh.material(f) != mesh.material(e) || normal.dot(mesh.normal(f)) < cosCrease) continue;
      const double difference = std::fabs(luminance[e] - luminance[f]);
      if (difference > floor && difference > options.threshold * std::max(luminance[e], luminance[f]))
        marked[e] = marked[f] = 1;
    }
  }
  std::vector<int> selected;
  for (int e = 0; e < n; ++e)
    if (marked[e] && mesh.area(e) > options.minArea) selected.push_back(e);
  return selected;
}

std::vector<int> refineElements(PatchMesh& mesh, const std::vector<int>& selected,
                                const RefinementOptions& options) {
  const int before = mesh.elementCount();
  // Corners of every element before, to find the ones a split changed.
  std::vector<std::array<int, 3>> corners(before);
  for (int e = 0; e < before; ++e) corners[e] = mesh.cornerVertices(e);
  for (int e : selected) {
    if (options.maxElements > 0 && mesh.elementCount() >= options.maxElements) break;
    // A split propagating from an earlier one may already have halved e.
    if (mesh.area(e) > options.minArea) mesh.bisect(e);
  }
  std::vector<int> changed;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (e >= before || mesh.cornerVertices(e) != corners[e]) changed.push_back(e);
  return changed;
}

}  // namespace rad
