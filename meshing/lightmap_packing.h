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
  int maxAtlasSize = 16384;
};

// A chart's own rectangle in the atlas, in texels. Rectangles never overlap, so each texel
// belongs to at most one chart; the chart's geometry lies at least `padding` texels inside.
struct ChartRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool rotated = false;  // turned by 90° to lie flat on its shelf
};

// Texel coordinates: x to the right, y down (row 0 at the top, as in EXR/PNG and glTF UVs);
// texel (i, j) covers [i, i+1) × [j, j+1) and its centre is (i + 0.5, j + 0.5).
struct LightmapLayout {
  int width = 0, height = 0;
  double texelSize = 0;
  int padding = 0;
  std::vector<ChartRect> rects;  // one per chart
  std::vector<int> chartOfElement;
  std::vector<std::array<Eigen::Vector2d, 3>> texels;  // element corners in texel coordinates

  // Normalised lightmap UV (glTF convention: origin at the top-left of the image).
  Eigen::Vector2d uv(int element, int corner) const {
    return {texels[element][corner].x() / width, texels[element][corner].y() / height};
  }
};

// Shelf packing of the charts' rectangles, tallest first. With options.texelSize the atlas grows
// to fit (about square); otherwise the texel size is the smallest (densest) that fits a square
// atlas of options.atlasSize. Throws InputError when the charts cannot fit (options too small).
LightmapLayout packLightmapCharts(const LightmapCharts& charts, const LightmapPackOptions& options);

}  // namespace rad
