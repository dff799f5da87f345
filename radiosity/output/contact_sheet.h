#pragma once

#include <string>
#include <vector>

#include "radiosity/core/image.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// One image of a contact sheet with the lines of text printed under it (printable ASCII).
struct SheetTile {
  ImageRgb image;  // linear radiance
  std::vector<std::string> label;
};

// Lays the tiles out left to right, `columns` per row, each tone-mapped with the same `toneMap`
// (so brightness compares across tiles) and labelled underneath in stb_easy_font's built-in
// bitmap font (no font files), doubled in size when the longest line fits. The result holds
// display values in [0, 1] before the sRGB curve: write it with ToneMap{1.0}.
ImageRgb composeContactSheet(const std::vector<SheetTile>& tiles, const ToneMap& toneMap,
                             int columns);

}  // namespace rad
