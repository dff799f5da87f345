#pragma once

// `radiosity bake` without the files: a solution baked into vertex colours and lightmap pages.
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/bake/bake_report.h"
#include "radiosity/bake/bake_spec.h"
#include "radiosity/bake/lightmap_plan.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/output/tone_map.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/render/directional_lightmap.h"

namespace rad {

struct BakeResult {
  explicit BakeResult(VertexInterpolation vertices) : interpolation(std::move(vertices)) {}

  // The vertex colours: the vertices (split at creases and material borders), B/π of the whole
  // at each, and of each light group's layer.
  VertexInterpolation interpolation;
  std::vector<Rgb> vertexRadiance;
  std::vector<std::vector<Rgb>> layerVertexRadiance;
  ToneMap toneMap;  // the 8-bit outputs' exposure
  // The lightmap, when the spec asks for one (else no pages): its layout, its pages (linear
  // outgoing radiance or H/π), their confidence map, each light group's pages, the directional
  // pages.
  LightmapLayout layout;
  std::vector<Lightmap> lightmaps, errorPages;
  std::vector<std::vector<Lightmap>> layerLightmaps;
  std::vector<DirectionalLightmapPage> directionalPages;
  BakeReport report;
};

// Bakes the solution `solved` holds (solved with `solveOptions`) as `spec` asks, in named steps
// that each add to the result's report: the vertex colours, the charts laid out on pages (the
// plan's layout when it is the solved mesh's own), the texels evaluated and dilated, their
// confidence, the light groups' layers, the directional pages. Light groups with a gather are a
// CheckFailure: the command refuses them (the gather cannot split its direct light).
BakeResult bakeSolution(const SolveResult& solved, const SolveOptions& solveOptions,
                        const BakeSpec& spec, const LightmapPlan& plan = {});

}  // namespace rad
