// PNG through libpng. Any bit depth, palette, grey or transparency layout comes out as 8-bit RGBA
// holding the file's own values (16-bit ones scaled to 8 bits): like stb_image and Blender, the
// file's gAMA chunk is not applied; the material says how the values are encoded. libpng reports
// fatal errors through a callback that must not return; it jumps back here (setjmp/longjmp, the
// library's documented way), and only C structs and already-constructed objects live across it.
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "radiosity/scene/image_decoders.h"

namespace rad::image_decoders {
namespace {

struct Cursor {
  const unsigned char* bytes;
  std::size_t size, at;
};

void readBytes(png_structp png, png_bytep out, png_size_t n) {
  auto* cursor = static_cast<Cursor*>(png_get_io_ptr(png));
  if (n > cursor->size - cursor->at) png_error(png, "the file ends early");
  std::memcpy(out, cursor->bytes + cursor->at, n);
  cursor->at += n;
}

constexpr std::size_t kMessageSize = 256;

[[noreturn]] void jumpOnError(png_structp png, png_const_charp message) {
  std::snprintf(static_cast<char*>(png_get_error_ptr(png)), kMessageSize, "%s", message);
  std::longjmp(png_jmpbuf(png), 1);
}

// Warnings (an ancillary chunk's bad CRC, an unknown chunk) keep the image, as image viewers do;
// they are not printed.
void ignoreWarning(png_structp, png_const_charp) {}

}  // namespace

std::string decodePng(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                      DecodedImage& image) {
  char message[kMessageSize] = "";
  Cursor cursor{bytes, size, 0};
  std::vector<png_bytep> rows;  // before setjmp: a jump must not skip its destructor
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, message, jumpOnError, ignoreWarning);
  if (!png) return "cannot start libpng";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return "cannot start libpng";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    image = DecodedImage{};
    return std::string("corrupt PNG: ") + message;
  }
  png_set_read_fn(png, &cursor, readBytes);
  png_read_info(png, info);
  {
    // Scoped: a later jump back to setjmp must not skip a live string's destructor.
    std::string refused =
        refuseSize(png_get_image_width(png, info), png_get_image_height(png, info));
    if (!refused.empty()) {
      png_destroy_read_struct(&png, &info, nullptr);
      return refused;
    }
  }
  png_set_expand(png);    // palette to RGB, grey below 8 bits to 8, tRNS to an alpha channel
  png_set_scale_16(png);  // 16 bits to 8, rounded
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);  // opaque where the file has no alpha
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  if (png_get_rowbytes(png, info) != rowBytes) png_error(png, "unexpected row layout");
  image.rgba8.resize(rowBytes * image.height);
  rows.resize(image.height);
  for (int y = 0; y < image.height; ++y) rows[y] = image.rgba8.data() + rowBytes * y;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return {};
}

}  // namespace rad::image_decoders
