#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "meshing/lightmap_charts.h"

namespace rad {

struct LightmapPackOptions {
  double texelSize = 0;  // scene units per texel; 0: the largest density that fits atlasSize
  int atlasSize = 1024;  // side of the square atlas when texelSize is 0
  int padding = 2;       // empty texels between a chart's geometry and its rectangle's edge
  // With texelSize: the largest side of a page; charts that do not fit one page go on more.
  int maxAtlasSize = 16384;
};

// The largest lightmap page `bake` writes at a texel density unless told otherwise: what
// current GPUs and engines accept as one texture everywhere.
constexpr int kDefaultMaxLightmapPage = 4096;

// A chart's own rectangle in the atlas, in texels. Rectangles never overlap, so each texel
// belongs to at most one chart; the chart's geometry lies at least `padding` texels inside.
struct ChartRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool rotated = false;  // turned by 90° to lie flat on its shelf
  int page = 0;          // the atlas page (texture) that holds it
};

// Texel coordinates: x to the right, y down (row 0 at the top, as in EXR/PNG and glTF UVs);
// texel (i, j) covers [i, i+1) × [j, j+1) of its chart's page and its centre is (i + 0.5, j + 0.5).
// Every page measures width × height; rects on one page never overlap.
struct LightmapLayout {
  int width = 0, height = 0;
  int pages = 1;
  double texelSize = 0;
  int padding = 0;
  std::vector<ChartRect> rects;  // one per chart
  std::vector<int> chartOfElement;
  std::vector<std::array<Eigen::Vector2d, 3>> texels;  // element corners in texel coordinates

  int page(int element) const { return rects[chartOfElement[element]].page; }

  // Normalised lightmap UV (glTF convention: origin at the top-left of the image).
  Eigen::Vector2d uv(int element, int corner) const {
    return {texels[element][corner].x() / width, texels[element][corner].y() / height};
  }
};

// Shelf packing of the charts' rectangles, tallest first. With options.texelSize the atlas grows
// to fit (about square) up to options.maxAtlasSize; charts that do not fit one page of that size
// go on further pages (each maxAtlasSize wide and as tall as the tallest page needs). Otherwise
// the texel size is the smallest (densest) that fits one square page of options.atlasSize.
// Throws InputError when the charts cannot fit (a chart larger than a page, options too small).
LightmapLayout packLightmapCharts(const LightmapCharts& charts, const LightmapPackOptions& options);

// The default texel size (scene units per texel) for a mesh: kDefaultLightmapTexels texels over
// its whole surface, so the lightmap's detail follows the scene and its texel count does not
// depend on the scene's unit (a scene scaled ×1000 gets texels ×1000 larger, as many of them).
constexpr double kDefaultLightmapTexels = 1048576;  // 1024², geometry only (padding adds more)
double defaultTexelSize(const PatchMesh& mesh);

}  // namespace rad
