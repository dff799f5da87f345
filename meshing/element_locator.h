#pragma once

#include <Eigen/Core>
#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

// Point location on a meshed patch: which element of a patch (input polygon) holds a point of
// that patch, and the point's barycentric weights in it. Solutions on different meshes of the
// same scene compare at the same points this way (one mesh's element centroids looked up in
// another's elements). Keeps a reference to `mesh`, which must outlive it.
class ElementLocator {
 public:
  explicit ElementLocator(const PatchMesh& mesh);

  // The element of `patch` containing p, with p's barycentric weights in it (weights[k] for
  // corner k of PatchMesh::corners; they sum to 1). Where rounding puts p just outside every
  // element of the patch: the one it is least outside of (the smallest negative weight is
  // largest), the first such in element order. -1 for a patch without elements.
  int locate(int patch, const Eigen::Vector3d& p, Eigen::Vector3d& weights) const;

 private:
  const PatchMesh& mesh_;
  std::vector<std::vector<int>> byPatch_;  // each patch's elements, in element order
};

}  // namespace rad
