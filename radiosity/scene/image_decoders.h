#pragma once

// The decoders behind decodeImage() (image_decode.h), one per library. Each returns an empty
// string on success and the library's message otherwise; each calls `refuseSize` with the header's
// dimensions before decoding any texel and stops with its message when that is not empty.

#include <cstddef>
#include <functional>
#include <string>

#include "radiosity/scene/image_decode.h"

namespace rad::image_decoders {

using SizeCheck = std::function<std::string(long long width, long long height)>;

std::string decodePng(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                      DecodedImage& image);
std::string decodeJpeg(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                       DecodedImage& image);
// BMP (every variant) and TIFF: `reader` is OpenImageIO's format name ("bmp", "tiff").
std::string decodeWithOpenImageIO(const char* reader, const unsigned char* bytes, std::size_t size,
                                  const SizeCheck& refuseSize, DecodedImage& image);
// TGA and Radiance HDR.
std::string decodeWithStb(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                          DecodedImage& image);

}  // namespace rad::image_decoders
