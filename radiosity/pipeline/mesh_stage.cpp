#include "radiosity/pipeline/mesh_stage.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

// Each polygon is one patch, in scene order. One whose triangles hold no area (or a NaN one)
// would be dropped silently by everything after; it is named by its `f` line instead.
void checkPatchAreas(const PatchMesh& mesh, const Scene& scene) {
  if (mesh.patchCount() != static_cast<int>(scene.polygons.size())) return;
  std::vector<double> areas(scene.polygons.size(), 0.0);
  for (int e = 0; e < mesh.elementCount(); ++e) areas[mesh.patch(e)] += mesh.area(e);
  for (std::size_t p = 0; p < areas.size(); ++p)
    if (!(areas[p] > 0) || !std::isfinite(areas[p]))
      throw InputError(scene.sourcePath, scene.polygons[p].sourceLine,
                       "this face triangulates to " +
                           std::string(std::isfinite(areas[p]) ? "no area" : "a non-finite area") +
                           " (a self-intersecting or degenerate polygon?)");
}

}  // namespace

MeshedScene meshScene(const Scene& scene, const SolveOptions& options) {
  MeshedScene out;
  out.mesh = std::make_unique<PatchMesh>(buildPatchMesh(scene));
  PatchMesh& mesh = *out.mesh;
  checkPatchAreas(mesh, scene);
  const double totalArea = mesh.totalArea();
  if (!(totalArea > 0) || !std::isfinite(totalArea))
    throw InputError(
        scene.sourcePath, 0,
        "the polygons triangulate to no area (self-intersecting or degenerate faces?)");
  out.maxArea = options.maxArea > 0 ? options.maxArea : totalArea / options.targetElements;
  // Bisection gives at most about 2·totalArea/maxArea elements.
  if (totalArea / out.maxArea > kMaxElements)
    throw InputError("about " + formatNumber(totalArea / out.maxArea) +
                     " elements requested (limit " + formatNumber(kMaxElements) +
                     "): raise --max-area or lower --elements");
  const bool analytic = options.formFactors == FormFactorMethod::Analytic;
  const double patchArea = options.patchArea > 0 ? options.patchArea : 8 * out.maxArea;
  {
    // The worst case of the form-factor rows must fit in memory.
    const double elements = std::ceil(totalArea / out.maxArea);
    const double patches = analytic ? std::ceil(totalArea / patchArea) : elements;
    checkFormFactorMemory(formFactorMemoryEstimate(options.formFactors, static_cast<int>(elements),
                                                   static_cast<int>(std::min(patches, elements)),
                                                   options.raysPerElement, options.receiverPoints),
                          availableMemoryBytes(), options.formFactors);
  }
  if (analytic) {
    // Shooting patches first (coarser), then elements inside them.
    if (patchArea < out.maxArea)
      throw InputError("--patch-area must not be below the element area");
    mesh.subdivideUniform(patchArea);
    mesh.markShooters();
  }
  mesh.subdivideUniform(out.maxArea);
  return out;
}

}  // namespace rad
