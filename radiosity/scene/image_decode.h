#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rad {

// An image file's texels as its decoder gives them, before any colour decoding: RGBA, rows top
// first. 8-bit formats (PNG, JPEG, TGA, BMP) fill `rgba8`; Radiance HDR fills `rgbaFloat` with
// its linear values. Alpha is 255 (or 1) where the file has none.
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba8;
  std::vector<float> rgbaFloat;
  bool isFloat() const { return !rgbaFloat.empty(); }
};

// Decodes PNG (libpng), JPEG (libjpeg-turbo), or TGA, BMP and Radiance HDR (stb_image), chosen by
// the file's first bytes. Images of more than `maxTexels` texels, and headers claiming more
// texels than their bytes can hold, are refused before any texel is decoded. Throws InputError
// naming `source` for anything it cannot read.
DecodedImage decodeImage(const unsigned char* bytes, std::size_t size, const std::string& source,
                         long long maxTexels);

}  // namespace rad
