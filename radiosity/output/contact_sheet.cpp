#include "radiosity/output/contact_sheet.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {
namespace {

constexpr int kMargin = 8;            // pixels between tiles and around the sheet
constexpr double kBackground = 0.01;  // display value of the sheet's background (near black)
constexpr int kLineHeight = 12;       // stb_easy_font's line advance at scale 1

// The display value the PNG writer would give this radiance, before its sRGB curve.
Rgb display(const Rgb& radiance, const ToneMap& toneMap) {
  Rgb out;
  for (int c = 0; c < 3; ++c) {
    const double v = toneMap.exposure * radiance[c];
    out[c] = std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0;
  }
  return out;
}

// stb_easy_font knows the printable ASCII range only.
std::string printable(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (c < 32 || c > 126) c = '?';
  return out;
}

int textWidth(const std::string& text) {
  std::string copy = printable(text);
  return stb_easy_font_width(copy.data());
}

// stb_easy_font draws each glyph as axis-aligned quads; fill them, scaled by `scale`.
void drawText(ImageRgb& sheet, int x0, int y0, const std::string& text, int scale) {
  std::string copy = printable(text);
  std::vector<char> buffer(std::max<size_t>(4096, copy.size() * 270 * 4));  // ~270 B per glyph
  const int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(),
                                        static_cast<int>(buffer.size()));
  const float* v = reinterpret_cast<const float*>(buffer.data());  // x, y, z, colour: 16 bytes
  for (int q = 0; q < quads; ++q) {
    const float* quad = v + q * 16;
    const float xa = quad[0], ya = quad[1], xb = quad[8], yb = quad[9];  // corners 0 and 2
    for (int y = static_cast<int>(std::lround(ya * scale)); y < std::lround(yb * scale); ++y)
      for (int x = static_cast<int>(std::lround(xa * scale)); x < std::lround(xb * scale); ++x) {
        const int px = x0 + x, py = y0 + y;
        if (px >= 0 && py >= 0 && px < sheet.width && py < sheet.height)
          sheet.at(px, py) = Rgb::all(1.0);
      }
  }
}

}  // namespace

ImageRgb composeContactSheet(const std::vector<SheetTile>& tiles, const ToneMap& toneMap,
                             int columns) {
  RAD_CHECK_MSG(!tiles.empty(), "a contact sheet needs at least one tile");
  RAD_CHECK_GE(columns, 1);
  columns = std::min<int>(columns, static_cast<int>(tiles.size()));
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  int cellW = 0, cellH = 0, widestLine = 0;
  size_t lines = 0;
  for (const SheetTile& t : tiles) {
    cellW = std::max(cellW, t.image.width);
    cellH = std::max(cellH, t.image.height);
    lines = std::max(lines, t.label.size());
    for (const std::string& line : t.label) widestLine = std::max(widestLine, textWidth(line));
  }
  const int scale = 2 * widestLine <= cellW ? 2 : 1;
  const int labelH = static_cast<int>(lines) * kLineHeight * scale + kMargin / 2;
  const int width = columns * cellW + (columns + 1) * kMargin;
  const int height = rows * (cellH + labelH) + (rows + 1) * kMargin;
  ImageRgb sheet(width, height);
  std::fill(sheet.pixels.begin(), sheet.pixels.end(), Rgb::all(kBackground));
  for (size_t i = 0; i < tiles.size(); ++i) {
    const int col = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    const int x0 = kMargin + col * (cellW + kMargin),
              y0 = kMargin + row * (cellH + labelH + kMargin);
    const ImageRgb& image = tiles[i].image;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        sheet.at(x0 + x, y0 + y) = display(image.at(x, y), toneMap);
    for (size_t k = 0; k < tiles[i].label.size(); ++k)
      drawText(sheet, x0,
               y0 + image.height + kMargin / 2 + static_cast<int>(k) * kLineHeight * scale,
               tiles[i].label[k], scale);
  }
  return sheet;
}

}  // namespace rad
