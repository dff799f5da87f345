#pragma once

#include <memory>

#include "meshing/patch_mesh.h"
#include "radiosity/pipeline/element_size.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The uniform mesh a solve starts from: every polygon a patch; slivers split into well-shaped
// elements; then split until no element is larger than the element area, or, for --elements,
// largest first until the count is met (decideElementSize says which rule applies); with
// analytic form factors, first into shooting patches (options.patchArea, default 8 × the element
// area) marked as shooters. Decided before any work: the element count and the worst case of the
// form-factor rows' memory must fit, and analytic factors must not need more than
// kMaxAnalyticShadowRays (InputError naming the options to change otherwise). A
// polygon that triangulates to no area is named by its line. Deterministic: re-meshing the same
// scene with the same options gives the same elements (saved solutions rely on it).
struct MeshedScene {
  std::unique_ptr<PatchMesh> mesh;
  double maxArea = 0;    // the element area bound (with --elements: the largest element)
  ElementSizing sizing;  // the rule and the size it chose
};
MeshedScene meshScene(const Scene& scene, const SolveOptions& options);

}  // namespace rad
