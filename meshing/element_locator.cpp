#include "meshing/element_locator.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace rad {

ElementLocator::ElementLocator(const PatchMesh& mesh) : mesh_(mesh), byPatch_(mesh.patchCount()) {
  for (int e = 0; e < mesh.elementCount(); ++e) byPatch_[mesh.patch(e)].push_back(e);
}

int ElementLocator::locate(int patch, const Eigen::Vector3d& p, Eigen::Vector3d& weights) const {
  int best = -1;
  double bestOutside = 1e300;
  for (int e : byPatch_[patch]) {
    const auto c = mesh_.corners(e);
    const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
    const double area2 = n.squaredNorm();
    Eigen::Vector3d w;
    for (int k = 0; k < 3; ++k)
      w[k] = (c[(k + 1) % 3] - p).cross(c[(k + 2) % 3] - p).dot(n) / area2;
    const double outside = -std::min(0.0, w.minCoeff());
    if (outside < bestOutside) {
      bestOutside = outside;
      best = e;
      weights = w;
      if (outside == 0) break;
    }
  }
  return best;
}

}  // namespace rad
