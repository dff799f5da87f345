#include "radiosity/scene/image_decode.h"

#include <cstring>

#include "radiosity/core/errors.h"
#include "radiosity/scene/image_decoders.h"

namespace rad {
namespace {

// No image format read here packs more texels into one byte: a 1-bit PNG at deflate's largest
// ratio (1032:1) gives about 8,300. A header claiming more states a size its data cannot hold
// (a decoder would pad the missing rows, and spend seconds doing so on a 60-byte file).
constexpr long long kMaxTexelsPerByte = 16384;

bool startsWith(const unsigned char* bytes, std::size_t size, const char* magic, std::size_t n) {
  return size >= n && std::memcmp(bytes, magic, n) == 0;
}

}  // namespace

DecodedImage decodeImage(const unsigned char* bytes, std::size_t size, const std::string& source,
                         long long maxTexels) {
  if (size == 0 || size > static_cast<std::size_t>(INT32_MAX))
    throw InputError(source, 0, "not a readable image (" + std::to_string(size) + " bytes)");
  const auto refuseSize = [&](long long w, long long h) -> std::string {
    if (w <= 0 || h <= 0 || w * h > maxTexels)
      return "image of " + std::to_string(w) + "×" + std::to_string(h) + " texels refused";
    if (w * h > kMaxTexelsPerByte * static_cast<long long>(size))
      return "image header claims " + std::to_string(w) + "×" + std::to_string(h) +
             " texels in only " + std::to_string(size) + " bytes: corrupt header";
    return {};
  };
  // PNG and JPEG, nearly every texture, go to the libraries every browser and image tool fuzzes
  // and patches; BMP (all its header versions and bit-field layouts) and TIFF to OpenImageIO;
  // stb_image reads only the simpler formats that remain (TGA, Radiance HDR).
  DecodedImage image;
  std::string error;
  if (startsWith(bytes, size, "\x89PNG\r\n\x1a\n", 8))
    error = image_decoders::decodePng(bytes, size, refuseSize, image);
  else if (startsWith(bytes, size, "\xff\xd8\xff", 3))
    error = image_decoders::decodeJpeg(bytes, size, refuseSize, image);
  else if (startsWith(bytes, size, "BM", 2))
    error = image_decoders::decodeWithOpenImageIO("bmp", bytes, size, refuseSize, image);
  else if (startsWith(bytes, size, "II*\0", 4) || startsWith(bytes, size, "MM\0*", 4))
    error = image_decoders::decodeWithOpenImageIO("tiff", bytes, size, refuseSize, image);
  else
    error = image_decoders::decodeWithStb(bytes, size, refuseSize, image);
  if (!error.empty()) throw InputError(source, 0, error);
  return image;
}

}  // namespace rad
