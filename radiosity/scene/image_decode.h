#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rad {

// An image file's texels as its decoder gives them, before any colour decoding: RGBA, rows top
// first. Integer formats (PNG, JPEG, TGA, BMP, 8- and 16-bit TIFF) fill `rgba8` (16-bit values
// rounded to 8); floating-point ones (Radiance HDR, float TIFF) fill `rgbaFloat` with their
// linear values. Grey is spread to RGB; alpha is 255 (or 1) where the file has none
// and is never multiplied into the colours.
struct DecodedImage {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba8;
  std::vector<float> rgbaFloat;
  bool isFloat() const { return !rgbaFloat.empty(); }
};

// Decodes PNG (libpng), JPEG (libjpeg-turbo), BMP of every variant and TIFF (OpenImageIO, what
// Blender reads images with), TGA and Radiance HDR (stb_image), chosen by the file's first bytes.
// Images of more than `maxTexels` texels, and headers claiming more texels than their bytes can
// hold, are refused before any texel is decoded. Throws InputError naming `source` for anything
// it cannot read (OpenEXR and DDS among them: oiio_decode.cpp says why).
DecodedImage decodeImage(const unsigned char* bytes, std::size_t size, const std::string& source,
                         long long maxTexels);

}  // namespace rad
