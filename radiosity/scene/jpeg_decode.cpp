// JPEG through libjpeg-turbo. libjpeg reports fatal errors through a callback that must not
// return; it jumps back here (setjmp/longjmp, the library's documented way), and only C structs
// and the caller's already-constructed image live across the jump.
#include <csetjmp>
#include <cstddef>
#include <cstdio>
// clang-format off: jpeglib.h needs size_t and FILE declared before it
#include <jpeglib.h>
// clang-format on

#include "radiosity/scene/image_decoders.h"

namespace rad::image_decoders {
namespace {

// Progressive JPEGs may hold any number of scans, each a pass over the whole image; libjpeg-turbo
// itself stops at 500 (TJFLAG_LIMITSCANS), far more than any encoder writes.
constexpr int kMaxScans = 500;

struct JpegErrors {
  jpeg_error_mgr manager;  // first, so libjpeg's pointer to it is a pointer to this struct
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jumpOnError(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  info->err->format_message(info, errors->message);
  std::longjmp(errors->jump, 1);
}

// Warnings (a few stray bytes, a truncated last scan) keep the image, as image viewers do; they
// are not printed.
void ignoreMessage(j_common_ptr) {}

void limitScans(j_common_ptr info) {
  auto* decompress = reinterpret_cast<j_decompress_ptr>(info);
  if (decompress->input_scan_number <= kMaxScans) return;
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  std::snprintf(errors->message, sizeof errors->message, "progressive JPEG of more than %d scans",
                kMaxScans);
  std::longjmp(errors->jump, 1);
}

}  // namespace

std::string decodeJpeg(const unsigned char* bytes, std::size_t size, const SizeCheck& refuseSize,
                       DecodedImage& image) {
  jpeg_decompress_struct info;
  JpegErrors errors;
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = jumpOnError;
  errors.manager.output_message = ignoreMessage;
  jpeg_progress_mgr progress{};
  progress.progress_monitor = limitScans;
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    image = DecodedImage{};
    return std::string("corrupt JPEG: ") + errors.message;
  }
  jpeg_create_decompress(&info);
  info.progress = &progress;
  jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
  jpeg_read_header(&info, TRUE);
  {
    // Scoped: a later jump back to setjmp must not skip a live string's destructor.
    std::string refused = refuseSize(info.image_width, info.image_height);
    if (!refused.empty()) {
      jpeg_destroy_decompress(&info);
      return refused;
    }
  }
  // CMYK and YCCK files (Adobe's, with inverted ink values) come out as CMYK and are multiplied
  // down to RGB below; everything else libjpeg-turbo converts to RGBA itself.
  const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
  info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  image.width = static_cast<int>(info.output_width);
  image.height = static_cast<int>(info.output_height);
  const std::size_t rowBytes = static_cast<std::size_t>(image.width) * 4;
  image.rgba8.resize(rowBytes * image.height);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = image.rgba8.data() + rowBytes * info.output_scanline;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  if (cmyk)
    for (std::size_t i = 0; i < image.rgba8.size(); i += 4) {
      unsigned char* t = &image.rgba8[i];
      const unsigned k = t[3];
      for (int c = 0; c < 3; ++c) t[c] = static_cast<unsigned char>((t[c] * k + 127) / 255);
      t[3] = 255;
    }
  return {};
}

}  // namespace rad::image_decoders
