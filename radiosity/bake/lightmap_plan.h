#pragma once

// Where the lightmap's charts go: the texel size's rule, and the layout planned before the solve.
#include <optional>
#include <string>

#include "meshing/lightmap_packing.h"
#include "meshing/patch_mesh.h"
#include "radiosity/bake/bake_spec.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// A layout and the rule that chose its texel size (for the log and bake.json).
struct LaidOutLightmap {
  LightmapLayout layout;
  std::string rule;
};

// The lightmap atlas of `mesh` as `spec` asks. The one place that decides:
//   lightmapSize alone         one square page of that side, the densest texels that fit;
//   texelSize/texelDensity     that density, on as many pages as needed of at most
//                              lightmapSize (default kDefaultMaxLightmapPage) texels a side;
//   neither                    the scene's default density (defaultTexelSize), pages as above.
// With the scene's UVs there is one page, its side from the density (at most the page size when
// the density is the default). InputError naming `scenePath` when the charts do not fit.
LaidOutLightmap layoutLightmap(const PatchMesh& mesh, const LightmapLayoutSpec& spec,
                               const std::string& scenePath);

// The layout decided before the solve, on the mesh the solve starts from, so that a lightmap
// size that cannot hold the charts fails in seconds, not after the solve.
struct LightmapPlan {
  // The layout, when it is the solved mesh's own: uniform meshing is deterministic, so without
  // refinement the planned mesh is the solved one. None: lay the charts out after the solve.
  std::optional<LaidOutLightmap> laidOut;
  double seconds = 0;
};

// Meshes `scene` as a solve with `options` would (after its scene limits' check) and lays the
// charts out on it; logs the plan.
LightmapPlan planLightmap(const Scene& scene, const SolveOptions& options,
                          const LightmapLayoutSpec& spec);

}  // namespace rad
