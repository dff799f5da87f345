// Image decoding (radiosity/scene/image_decode.h): PNG through libpng and JPEG through
// libjpeg-turbo, each in the layouts real textures use, against images the same libraries'
// encoders write from known texels; and the errors that name the file.
#include <gtest/gtest.h>
#include <png.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
// clang-format off: jpeglib.h needs size_t and FILE declared before it
#include <jpeglib.h>
// clang-format on

#include "radiosity/core/errors.h"
#include "radiosity/scene/image_decode.h"

namespace rad {
namespace {

// A PNG of `texels` (rows top first) in libpng's simplified `format`.
std::vector<unsigned char> png(int w, int h, png_uint_32 format, const void* texels) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = w, image.height = h, image.format = format;
  png_alloc_size_t size = 0;
  EXPECT_TRUE(png_image_write_to_memory(&image, nullptr, &size, 0, texels, 0, nullptr));
  std::vector<unsigned char> out(size);
  EXPECT_TRUE(png_image_write_to_memory(&image, out.data(), &size, 0, texels, 0, nullptr))
      << image.message;
  out.resize(size);
  return out;
}

// A JPEG of `samples` (rows top first, `components` per texel in `space`), at quality 95,
// baseline or progressive.
std::vector<unsigned char> jpeg(int w, int h, J_COLOR_SPACE space, int components,
                                const std::vector<unsigned char>& samples,
                                bool progressive = false) {
  jpeg_compress_struct info;
  jpeg_error_mgr errors;
  info.err = jpeg_std_error(&errors);
  jpeg_create_compress(&info);
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = w, info.image_height = h;
  info.input_components = components, info.in_color_space = space;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, 95, TRUE);
  if (progressive) jpeg_simple_progression(&info);
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    JSAMPROW row = const_cast<unsigned char*>(&samples[info.next_scanline * w * components]);
    jpeg_write_scanlines(&info, &row, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::vector<unsigned char> out(buffer, buffer + size);
  std::free(buffer);
  return out;
}

DecodedImage decode(const std::vector<unsigned char>& bytes, const std::string& name) {
  return decodeImage(bytes.data(), bytes.size(), name, 1LL << 26);
}

std::string errorOf(const std::vector<unsigned char>& bytes, const std::string& name) {
  try {
    decode(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << " decoded without an error";
  return "";
}

// Every texel of `image` is `rgba` within `tolerance` levels.
void expectFlat(const DecodedImage& image, std::vector<int> rgba, int tolerance) {
  ASSERT_FALSE(image.isFloat());
  ASSERT_EQ(image.rgba8.size(), static_cast<std::size_t>(image.width) * image.height * 4);
  for (std::size_t i = 0; i < image.rgba8.size(); ++i)
    ASSERT_NEAR(image.rgba8[i], rgba[i % 4], tolerance) << "value " << i;
}

TEST(ImageDecode, PngLayoutsAllComeOutAsTheFilesRgbaValues) {
  // RGBA: exact, rows top first.
  const std::vector<unsigned char> rgba = {10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120};
  const DecodedImage a = decode(png(1, 3, PNG_FORMAT_RGBA, rgba.data()), "a.png");
  ASSERT_EQ(a.width, 1);
  ASSERT_EQ(a.height, 3);
  EXPECT_EQ(a.rgba8, rgba);
  // Grey: spread to RGB, opaque.
  const std::vector<unsigned char> grey = {77, 77};
  expectFlat(decode(png(2, 1, PNG_FORMAT_GRAY, grey.data()), "g.png"), {77, 77, 77, 255}, 0);
  // RGB without alpha: opaque.
  const std::vector<unsigned char> rgb = {200, 100, 50};
  expectFlat(decode(png(1, 1, PNG_FORMAT_RGB, rgb.data()), "rgb.png"), {200, 100, 50, 255}, 0);
}

TEST(ImageDecode, SixteenBitPngKeepsItsValuesScaledToEightBits) {
  // libpng's simplified writer stores 16-bit data as linear, with a gAMA chunk saying so. The
  // decoder does not apply gAMA (the material says how values are encoded), so 16-bit v comes out
  // as v / 257 within rounding: 0x8080 → 128, 0xffff → 255, 0x1010 → 16.
  const std::vector<png_uint_16> rgba = {0x8080, 0xffff, 0x1010, 0xffff};
  expectFlat(decode(png(1, 1, PNG_FORMAT_LINEAR_RGB_ALPHA, rgba.data()), "deep.png"),
             {128, 255, 16, 255}, 0);
}

TEST(ImageDecode, JpegInRgbGreyCmykAndProgressiveDecodesToItsColour) {
  // A flat colour survives JPEG within a few levels (quality 95, no edges to ring).
  const int w = 16, h = 8;
  std::vector<unsigned char> rgb;
  for (int i = 0; i < w * h; ++i) rgb.insert(rgb.end(), {200, 100, 50});
  expectFlat(decode(jpeg(w, h, JCS_RGB, 3, rgb), "rgb.jpg"), {200, 100, 50, 255}, 3);
  expectFlat(decode(jpeg(w, h, JCS_RGB, 3, rgb, true), "progressive.jpg"), {200, 100, 50, 255}, 3);
  const std::vector<unsigned char> grey(w * h, 90);
  expectFlat(decode(jpeg(w, h, JCS_GRAYSCALE, 1, grey), "grey.jpg"), {90, 90, 90, 255}, 2);
  // Adobe CMYK stores inverted inks: a texel is (255 − C, 255 − M, 255 − Y, 255 − K), and its
  // colour is each of the first three times the fourth / 255. Half black over (200, 100, 50)
  // gives (100, 50, 25).
  std::vector<unsigned char> cmyk;
  for (int i = 0; i < w * h; ++i) cmyk.insert(cmyk.end(), {200, 100, 50, 128});
  expectFlat(decode(jpeg(w, h, JCS_CMYK, 4, cmyk), "cmyk.jpg"), {100, 50, 25, 255}, 3);
}

TEST(ImageDecode, CorruptPngAndJpegNameTheFileAndWhatIsWrong) {
  const std::vector<unsigned char> rgb = {200, 100, 50, 200, 100, 50};
  auto goodPng = png(2, 1, PNG_FORMAT_RGB, rgb.data());
  // Cut in the middle of the image data.
  const std::vector<unsigned char> cutPng(goodPng.begin(), goodPng.begin() + goodPng.size() - 20);
  const std::string p = errorOf(cutPng, "cut.png");
  EXPECT_NE(p.find("cut.png"), std::string::npos) << p;
  EXPECT_NE(p.find("PNG"), std::string::npos) << p;
  // A JPEG cut inside its header (before the image data) cannot be read at all.
  std::vector<unsigned char> grey(64, 90);
  auto goodJpeg = jpeg(8, 8, JCS_GRAYSCALE, 1, grey);
  const std::vector<unsigned char> cutJpeg(goodJpeg.begin(), goodJpeg.begin() + 40);
  const std::string j = errorOf(cutJpeg, "cut.jpg");
  EXPECT_NE(j.find("cut.jpg"), std::string::npos) << j;
  EXPECT_NE(j.find("JPEG"), std::string::npos) << j;
  // Neither PNG, JPEG, TGA, BMP nor HDR.
  const std::string text =
      errorOf({'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd'}, "a.txt");
  EXPECT_NE(text.find("a.txt"), std::string::npos) << text;
  EXPECT_NE(text.find("not a readable image"), std::string::npos) << text;
}

TEST(ImageDecode, SizeLimitsApplyToPngAndJpegHeadersBeforeDecoding) {
  // A 4×4 image with a cap of 15 texels is refused, naming its size; with 16 it decodes.
  const std::vector<unsigned char> grey(16, 7);
  for (const auto& bytes :
       {png(4, 4, PNG_FORMAT_GRAY, grey.data()), jpeg(4, 4, JCS_GRAYSCALE, 1, grey)}) {
    try {
      decodeImage(bytes.data(), bytes.size(), "small", 15);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("4×4"), std::string::npos) << e.what();
    }
    EXPECT_EQ(decodeImage(bytes.data(), bytes.size(), "small", 16).width, 4);
  }
}

}  // namespace
}  // namespace rad
