#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/patch_mesh.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/image.h"
#include "radiosity/core/rgb.h"

namespace rad {

enum class TexelState : std::uint8_t {
  Empty,         // outside every chart's reach: black
  Covered,       // its centre lies in an element: the solution there
  Conservative,  // an element overlaps it but not its centre: the solution at the nearest point
  Dilated,       // filled from neighbours of the same chart, so bilinear filtering does not bleed
};

// A baked lightmap: linear outgoing radiance (W·m⁻²·sr⁻¹) per texel, and which chart and element
// each texel belongs to (for tests and statistics).
struct Lightmap {
  ImageRgb radiance;
  std::vector<int> chart;    // per texel, -1 where Empty
  std::vector<int> element;  // per texel, -1 where Dilated or Empty
  std::vector<TexelState> state;
  int dilationRadius = 0;
  // Texels next to the own (covered or partly covered) texels of two charts, where bilinear
  // filtering bleeds between them: 0 for packed charts; scene UVs may put islands that close.
  size_t crowdedTexels = 0;

  size_t index(int x, int y) const { return static_cast<size_t>(y) * radiance.width + x; }
  size_t count(TexelState s) const;
};

// Rasterises every element into its chart's texels and evaluates the solution there: the
// barycentric interpolation of `vertexRadiance` (one per output vertex of `interpolation`) over
// the element holding the texel centre. Texels an element only partly covers take the value at
// the element's point nearest their centre, so every element owns texels and bilinear lookups
// inside an element read only its chart. Then `dilationRadius` rings of empty texels around each
// chart (at most the layout's padding) take the mean of their filled neighbours of one chart —
// never of two; a texel next to the own texels of two charts stays empty. Throws
// CheckFailure (RAD_CHECK) when dilationRadius exceeds the padding.
//
// With `evaluate`, every texel an element covers (fully or in part) takes evaluate(element,
// barycentric, texel) instead of the interpolated value — e.g. a per-texel final gather — computed
// in parallel before the dilation.
//
// One call bakes one page of the layout (`page` < layout.pages): the elements of the charts on it.
using TexelEvaluator =
    std::function<Rgb(int element, const Eigen::Vector3d& barycentric, size_t texel)>;
Lightmap bakeLightmap(const PatchMesh& mesh, const LightmapLayout& layout,
                      const VertexInterpolation& interpolation,
                      const std::vector<Rgb>& vertexRadiance, int dilationRadius,
                      const TexelEvaluator& evaluate = {}, int page = 0);

// Another quantity on the texels of `shape`, a page bakeLightmap made on `layout` (the confidence
// map, a light group's layer, a directional coefficient): every texel an element owns takes
// evaluate(element, barycentric, texel) at the weights bakeLightmap gave it, and the dilated rings
// are filled from those values as bakeLightmap fills them. The same page as bakeLightmap with
// that evaluator, texel for texel, without rasterising the elements again.
Lightmap bakeOnTexels(const Lightmap& shape, const LightmapLayout& layout,
                      const TexelEvaluator& evaluate);

}  // namespace rad
