#include "radiosity/pipeline/mesh_stage.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/element_size.h"
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

// Analytic factors cost every element a shadow-ray set per shooting patch, and every input
// polygon is at least one patch: on a scene of tens of thousands of polygons the worst case is
// hours. Refused before the form factors start, with the estimate.
void checkAnalyticCost(const PatchMesh& mesh, const SolveOptions& options) {
  const double rays = static_cast<double>(mesh.elementCount()) * mesh.shooterCount() *
                      options.receiverPoints * options.shadowRays;
  if (rays <= kMaxAnalyticShadowRays) return;
  throw InputError(
      "--form-factors analytic is impractical here: " + std::to_string(mesh.elementCount()) +
      " elements × " + std::to_string(mesh.shooterCount()) +
      " shooting patches (every input polygon is at least one) × " +
      std::to_string(options.receiverPoints) + " receiver points × " +
      std::to_string(options.shadowRays) + " shadow rays is up to " + formatNumber(rays) +
      " shadow rays, about " + formatNumber(rays / kAssumedShadowRaysPerSecond / 3600) +
      " hours at 10 million rays per second (limit " + formatNumber(kMaxAnalyticShadowRays) +
      "); use --form-factors hemisphere");
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
  out.sizing = decideElementSize(options, totalArea, mesh.boundsDiagonal());
  const ElementSizing& sizing = out.sizing;
  out.maxArea = sizing.maxArea;
  // Bisection to an area bound gives at most about 2·totalArea/maxArea elements.
  const double expectedElements =
      sizing.targetCount > 0 ? sizing.targetCount : totalArea / sizing.maxArea;
  if (expectedElements > kMaxElements)
    throw InputError("about " + formatNumber(expectedElements) + " elements requested (limit " +
                     formatNumber(kMaxElements) +
                     "): raise --element-size or --max-area, or lower --elements");
  const double elementArea = equilateralArea(sizing.edge);
  const bool analytic = options.formFactors == FormFactorMethod::Analytic;
  const double patchArea = options.patchArea > 0 ? options.patchArea : 8 * elementArea;
  {
    // The worst case of the form-factor rows must fit in memory.
    const double elements = std::max(std::ceil(totalArea / elementArea),
                                     static_cast<double>(mesh.inputTriangleCount()));
    const double patches = analytic ? std::ceil(totalArea / patchArea) : elements;
    checkFormFactorMemory(formFactorMemoryEstimate(options.formFactors, static_cast<int>(elements),
                                                   static_cast<int>(std::min(patches, elements)),
                                                   options.raysPerElement, options.receiverPoints),
                          availableMemoryBytes(), options.formFactors);
  }
  // Slivers first, whatever the size rule: a sliver smaller than the element area is still
  // faceted along its length.
  mesh.splitSlivers(kMaxAspectRatio, sizing.edge / kSliverEdgeFraction);
  if (analytic) {
    // Shooting patches first (coarser), then elements inside them.
    if (patchArea < elementArea)
      throw InputError("--patch-area must not be below the element area");
    mesh.subdivideUniform(patchArea);
    mesh.markShooters();
  }
  if (sizing.targetCount > 0) {
    mesh.subdivideToCount(sizing.targetCount);
    // A scene whose own triangles (sliver splits included) already number N or more has spent
    // the count on them: its large surfaces would stay whole (Sponza's floor in 1.4 m² elements
    // and 144 m² walls at --elements 300000) and blur the light they bounce. They are split
    // on to the bound a mesh of N equal elements stays under.
    mesh.subdivideUniform(kCountedMaxAreaOverMean * totalArea / sizing.targetCount);
    for (int e = 0; e < mesh.elementCount(); ++e) out.maxArea = std::max(out.maxArea, mesh.area(e));
  } else
    mesh.subdivideUniform(sizing.maxArea);
  if (analytic) checkAnalyticCost(mesh, options);
  return out;
}

}  // namespace rad
