#include "meshing/lightmap_packing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {
namespace {

struct Sized {
  int width, height;
  bool rotated;
};

std::vector<Sized> rectSizes(const LightmapCharts& charts, double texelSize, int padding) {
  std::vector<Sized> sizes;
  for (const LightmapChart& c : charts.charts) {
    // At least one texel of geometry, so a tiny chart still owns texels.
    const int w =
        std::max(1, static_cast<int>(std::ceil(c.size.x() / texelSize - 1e-9))) + 2 * padding;
    const int h =
        std::max(1, static_cast<int>(std::ceil(c.size.y() / texelSize - 1e-9))) + 2 * padding;
    sizes.push_back(h > w ? Sized{h, w, true} : Sized{w, h, false});
  }
  return sizes;
}

struct Shelves {
  int pages = 1;
  int height = 0;  // of the tallest page
};

// Places rectangles on shelves of `atlasWidth`, starting a new page where a shelf would pass
// `pageHeight`. Returns height INT_MAX if a chart is wider than the atlas.
Shelves shelfPack(const std::vector<Sized>& sizes, int atlasWidth, int pageHeight,
                  std::vector<ChartRect>& rects) {
  std::vector<int> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return sizes[a].height != sizes[b].height ? sizes[a].height > sizes[b].height
                                              : sizes[a].width > sizes[b].width;
  });
  rects.assign(sizes.size(), {});
  Shelves used;
  int x = 0, y = 0, shelf = 0, page = 0;
  for (int i : order) {
    if (sizes[i].width > atlasWidth) return {1, std::numeric_limits<int>::max()};
    if (x + sizes[i].width > atlasWidth) y += shelf, x = 0, shelf = 0;
    if (y + sizes[i].height > pageHeight && y > 0) ++page, x = 0, y = 0, shelf = 0;
    rects[i] = {x, y, sizes[i].width, sizes[i].height, sizes[i].rotated, page};
    x += sizes[i].width;
    shelf = std::max(shelf, sizes[i].height);
    used.height = std::max(used.height, y + shelf);
  }
  used.pages = page + 1;
  return used;
}

int shelfPack(const std::vector<Sized>& sizes, int atlasWidth, std::vector<ChartRect>& rects) {
  return shelfPack(sizes, atlasWidth, std::numeric_limits<int>::max(), rects).height;
}

}  // namespace

LightmapLayout packLightmapCharts(const LightmapCharts& charts,
                                  const LightmapPackOptions& options) {
  RAD_CHECK_GE(options.padding, 1);
  RAD_CHECK_MSG(!charts.charts.empty(), "no lightmap charts to pack");
  double area = 0;
  for (const LightmapChart& c : charts.charts) area += std::max(c.size.x() * c.size.y(), 1e-300);

  LightmapLayout layout;
  layout.padding = options.padding;
  std::vector<ChartRect> rects;
  if (options.texelSize > 0) {
    layout.texelSize = options.texelSize;
    const std::vector<Sized> sizes = rectSizes(charts, options.texelSize, options.padding);
    const int maxSide = options.maxAtlasSize;
    double rectArea = 0;
    int widest = 0;
    for (const Sized& s : sizes)
      rectArea += double(s.width) * s.height, widest = std::max(widest, s.width);
    if (widest > maxSide)
      throw InputError("a lightmap chart needs " + std::to_string(widest) +
                       " texels at texel size " + std::to_string(options.texelSize) +
                       " (padding included), more than a page of " + std::to_string(maxSide) +
                       " texels; lower --texel-density or raise --lightmap-size");
    int width = std::max(widest, static_cast<int>(std::ceil(std::sqrt(rectArea / 0.85))));
    int height =
        width <= maxSide ? shelfPack(sizes, width, rects) : std::numeric_limits<int>::max();
    // Widen until the atlas is about square (shelves waste some of the estimate).
    while (width < maxSide && height > width * 1.1) {
      width = std::min(maxSide, static_cast<int>(width * 1.05) + 1);
      height = shelfPack(sizes, width, rects);
    }
    if (width > maxSide || height > maxSide) {
      // More than one page: full-width pages, each filled before the next begins.
      width = maxSide;
      const Shelves shelves = shelfPack(sizes, width, maxSide, rects);
      RAD_CHECK_LE(shelves.height, maxSide);  // every chart fits a page (checked above)
      layout.pages = shelves.pages;
      height = shelves.height;
    }
    layout.width = width;
    layout.height = height;
  } else {
    const int side = options.atlasSize;
    if (side < 1 + 2 * options.padding)
      throw InputError("lightmap size " + std::to_string(side) + " too small for a padding of " +
                       std::to_string(options.padding) + " texels; raise --lightmap-size");
    auto fits = [&](double t) {
      return shelfPack(rectSizes(charts, t, options.padding), side, rects) <= side;
    };
    // A coarse texel first: the geometry would fill the atlas exactly, padding aside.
    double hi = std::sqrt(area) / side, lo = hi;
    for (int i = 0; i < 200 && !fits(hi); ++i) hi *= 2;
    if (!fits(hi))
      throw InputError(std::to_string(charts.charts.size()) + " charts with " +
                       std::to_string(options.padding) + " texels of padding do not fit a " +
                       std::to_string(side) +
                       "² lightmap; raise --lightmap-size, or give --texel-density (without "
                       "--lightmap-size) to spread them over several pages");
    while (fits(lo)) lo *= 0.5;
    for (int i = 0; i < 40; ++i) {  // bisection in log space: densest texel that still fits
      const double mid = std::sqrt(lo * hi);
      (fits(mid) ? hi : lo) = mid;
    }
    layout.texelSize = hi;
    shelfPack(rectSizes(charts, hi, options.padding), side, rects);
    layout.width = layout.height = side;
  }
  layout.rects = rects;

  layout.chartOfElement = charts.chartOfElement;
  layout.texels.resize(charts.corners.size());
  for (size_t e = 0; e < charts.corners.size(); ++e) {
    const int c = charts.chartOfElement[e];
    const ChartRect& r = layout.rects[c];
    const Eigen::Vector2d size = charts.charts[c].size;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector2d q = charts.corners[e][k];
      if (r.rotated) q = Eigen::Vector2d(size.y() - q.y(), q.x());  // a rotation: no mirroring
      const double top = r.rotated ? size.x() : size.y();
      // Texel y grows downwards: flip so the chart keeps its winding with v up (OBJ, Blender).
      layout.texels[e][k] =
          Eigen::Vector2d(r.x + options.padding + q.x() / layout.texelSize,
                          r.y + options.padding + (top - q.y()) / layout.texelSize);
    }
  }
  return layout;
}

double defaultTexelSize(const PatchMesh& mesh) {
  double area = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) area += mesh.area(e);
  RAD_CHECK_GT(area, 0.0);
  return std::sqrt(area / kDefaultLightmapTexels);
}

}  // namespace rad
