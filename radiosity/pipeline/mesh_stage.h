#pragma once

#include <memory>

#include "meshing/patch_mesh.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The uniform mesh a solve starts from: every polygon a patch, split until no element is larger
// than the element area (options.maxArea, or the total area / options.targetElements); with
// analytic form factors, first into shooting patches (options.patchArea, default 8 × the element
// area) marked as shooters. Decided before any work: the element count and the worst case of the
// form-factor rows' memory must fit (InputError naming the options to change otherwise). A
// polygon that triangulates to no area is named by its line. Deterministic: re-meshing the same
// scene with the same options gives the same elements (saved solutions rely on it).
struct MeshedScene {
  std::unique_ptr<PatchMesh> mesh;
  double maxArea = 0;  // the element area used
};
MeshedScene meshScene(const Scene& scene, const SolveOptions& options);

}  // namespace rad
