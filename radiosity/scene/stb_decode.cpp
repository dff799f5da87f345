// TGA and Radiance HDR through stb_image, compiled privately into this file only (libstb-dev's
// header). PNG and JPEG are read by libpng and libjpeg-turbo, BMP by OpenImageIO instead; they
// are compiled out of stb here so that no file can reach its decoders for them.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_PNG
#define STBI_NO_JPEG
#define STBI_NO_BMP
#define STBI_NO_PSD
#define STBI_NO_GIF
#define STBI_NO_PIC
#define STBI_NO_PNM
#define STBI_FAILURE_USERMSG
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <memory>

#include "radiosity/scene/image_decoders.h"

namespace rad::image_decoders {

std::string decodeWithStb(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                          DecodedImage& image) {
  const int length = static_cast<int>(size);  // decodeImage refuses anything over INT32_MAX
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, length, &w, &h, &channels))
    return std::string("not a readable image (PNG, JPEG, BMP, TIFF, TGA or Radiance HDR): ") +
           stbi_failure_reason();
  const std::string refused = refuseSize(w, h);
  if (!refused.empty()) return refused;
  const std::size_t values = static_cast<std::size_t>(w) * h * 4;
  int loadedW = 0, loadedH = 0;
  if (stbi_is_hdr_from_memory(bytes, length)) {
    std::unique_ptr<float, void (*)(void*)> data(
        stbi_loadf_from_memory(bytes, length, &loadedW, &loadedH, &channels, 4), stbi_image_free);
    if (!data) return std::string("corrupt image: ") + stbi_failure_reason();
    if (loadedW != w || loadedH != h) return "corrupt image: its size changed while decoding";
    image.rgbaFloat.assign(data.get(), data.get() + values);
  } else {
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load_from_memory(bytes, length, &loadedW, &loadedH, &channels, 4), stbi_image_free);
    if (!data) return std::string("corrupt image: ") + stbi_failure_reason();
    if (loadedW != w || loadedH != h) return "corrupt image: its size changed while decoding";
    image.rgba8.assign(data.get(), data.get() + values);
  }
  image.width = w;
  image.height = h;
  return {};
}

}  // namespace rad::image_decoders
