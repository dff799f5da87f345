// Image decoding (radiosity/scene/image_decode.h): PNG and JPEG in the
// layouts real textures use, against images libpng's and libjpeg-turbo's own encoders write from
// known texels; BMP (classic and the 16-bit bit-field variant with a V3 header), Radiance HDR
// and TIFF written here byte by byte from their specifications; DDS and OpenEXR refused; and the
// errors that name the file.
#include <ImfArray.h>
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <png.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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

// Little-endian fields appended to a byte string, as the BMP, TIFF and DDS headers store them.
void put16(std::vector<unsigned char>& b, uint32_t v) {
  for (int i = 0; i < 2; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
}
void put32(std::vector<unsigned char>& b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

// A 2×1 BMP: 24-bit BGR with a BITMAPINFOHEADER, or 16-bit BI_BITFIELDS (R 0x0F00, G 0x00F0,
// B 0x000F, alpha 0xF000: 4 bits each) with a 56-byte BITMAPV3INFOHEADER, the variant Maya
// writes. Texels: red, then green.
std::vector<unsigned char> bmp(bool sixteenBit) {
  std::vector<unsigned char> pixels;
  if (sixteenBit) {
    put16(pixels, 0xFF00);  // alpha 15, red 15
    put16(pixels, 0x80F0);  // alpha 8, green 15
  } else {
    pixels = {0, 0, 255, 0, 255, 0, 0, 0};  // BGR red, BGR green, 2 bytes of row padding
  }
  const uint32_t headerSize = sixteenBit ? 56 : 40, offset = 14 + headerSize;
  std::vector<unsigned char> b = {'B', 'M'};
  put32(b, offset + static_cast<uint32_t>(pixels.size()));
  put32(b, 0);
  put32(b, offset);
  put32(b, headerSize);
  put32(b, 2);                     // width
  put32(b, 1);                     // height (bottom-up)
  put16(b, 1);                     // planes
  put16(b, sixteenBit ? 16 : 24);  // bits per pixel
  put32(b, sixteenBit ? 3 : 0);    // BI_BITFIELDS or BI_RGB
  put32(b, static_cast<uint32_t>(pixels.size()));
  put32(b, 2835), put32(b, 2835), put32(b, 0), put32(b, 0);
  if (sixteenBit) put32(b, 0x0F00), put32(b, 0x00F0), put32(b, 0x000F), put32(b, 0xF000);
  b.insert(b.end(), pixels.begin(), pixels.end());
  return b;
}

TEST(ImageDecode, BmpClassicAndSixteenBitBitFieldsWithAV3Header) {
  for (const bool sixteenBit : {false, true}) {
    const std::vector<unsigned char> bytes = bmp(sixteenBit);
    const DecodedImage image = decodeImage(bytes.data(), bytes.size(), "zebra.bmp", 1 << 20);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 1);
    ASSERT_EQ(image.rgba8.size(), 8u);
    // 4-bit 15 and 8-bit 255 are both full scale.
    EXPECT_EQ(image.rgba8[0], 255) << sixteenBit;
    EXPECT_EQ(image.rgba8[1], 0) << sixteenBit;
    EXPECT_EQ(image.rgba8[2], 0) << sixteenBit;
    EXPECT_EQ(image.rgba8[4], 0) << sixteenBit;
    EXPECT_EQ(image.rgba8[5], 255) << sixteenBit;
    EXPECT_EQ(image.rgba8[6], 0) << sixteenBit;
  }
}

// A 2×1 Radiance HDR, flat (not run-length) RGBE texels: 1.5 (mantissa 192, exponent 129) and
// 0.25 (128, 127) in every channel.
TEST(ImageDecode, RadianceHdrKeepsItsLinearValues) {
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n";
  std::vector<unsigned char> bytes(header.begin(), header.end());
  for (const unsigned char v : {192, 192, 192, 129, 128, 128, 128, 127}) bytes.push_back(v);
  const DecodedImage image = decodeImage(bytes.data(), bytes.size(), "sky.hdr", 1 << 20);
  ASSERT_TRUE(image.isFloat());
  ASSERT_EQ(image.rgbaFloat.size(), 8u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_FLOAT_EQ(image.rgbaFloat[c], 1.5f);
    EXPECT_FLOAT_EQ(image.rgbaFloat[4 + c], 0.25f);
  }
  EXPECT_FLOAT_EQ(image.rgbaFloat[3], 1.0f);
}

// A 2×1 uncompressed 8-bit RGBA TIFF, little-endian: a header, the texels, one IFD.
TEST(ImageDecode, TiffRgbaKeepsItsUnassociatedAlpha) {
  std::vector<unsigned char> b = {'I', 'I', 42, 0};
  const std::vector<unsigned char> texels = {200, 100, 50, 128, 10, 20, 30, 255};
  put32(b, 8 + static_cast<uint32_t>(texels.size()));  // the IFD after the texels
  b.insert(b.end(), texels.begin(), texels.end());
  const uint32_t ifd = static_cast<uint32_t>(b.size());
  const uint32_t bitsAt = ifd + 2 + 11 * 12 + 4;  // BitsPerSample's four values after the IFD
  const uint32_t entries[][3] = {
      {256, 3, 2}, {257, 3, 1}, {258, 3, bitsAt},  // width, height, bits (4 values)
      {259, 3, 1}, {262, 3, 2}, {273, 4, 8},       // no compression, RGB, strip at 8
      {277, 3, 4}, {278, 3, 1}, {279, 4, 8},       // 4 samples, 1 row, 8 bytes
      {284, 3, 1}, {338, 3, 2}};                   // chunky, unassociated alpha
  put16(b, 11);
  for (const auto& e : entries) {
    put16(b, e[0]);
    put16(b, e[1]);
    put32(b, e[0] == 258 ? 4 : 1);
    if (e[1] == 3 && e[0] != 258) {
      put16(b, e[2]);
      put16(b, 0);
    } else {
      put32(b, e[2]);
    }
  }
  put32(b, 0);  // no next IFD
  for (int i = 0; i < 4; ++i) put16(b, 8);
  const DecodedImage image = decodeImage(b.data(), b.size(), "wall.tif", 1 << 20);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.rgba8.size(), 8u);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(image.rgba8[i], texels[i]) << i;
}

// A 2×1 uncompressed 32-bit DDS (DDPF_RGB | DDPF_ALPHAPIXELS, A8R8G8B8) is refused, naming the
// file: Debian 12's OpenImageIO reads DDS but hung on a malformed one (oiio_decode.cpp).
TEST(ImageDecode, DdsIsRefusedNamingTheFile) {
  std::vector<unsigned char> b = {'D', 'D', 'S', ' '};
  put32(b, 124);                          // header size
  put32(b, 0x1 | 0x2 | 0x4 | 0x1000);     // caps, height, width, pixel format
  put32(b, 1), put32(b, 2);               // height, width
  put32(b, 8), put32(b, 0), put32(b, 0);  // pitch, depth, mipmaps
  for (int i = 0; i < 11; ++i) put32(b, 0);
  put32(b, 32), put32(b, 0x40 | 0x1), put32(b, 0), put32(b, 32);  // pixel format: RGB + alpha
  put32(b, 0x00FF0000), put32(b, 0x0000FF00), put32(b, 0x000000FF), put32(b, 0xFF000000);
  put32(b, 0x1000), put32(b, 0), put32(b, 0), put32(b, 0), put32(b, 0);  // caps: texture
  for (const unsigned char v : {50, 100, 200, 255, 30, 20, 10, 64}) b.push_back(v);
  const std::string message = errorOf(b, "floor.dds");
  EXPECT_NE(message.find("floor.dds"), std::string::npos) << message;
  EXPECT_NE(message.find("not a readable image"), std::string::npos) << message;
}

// OpenEXR, even as OpenEXR's own writer stores it, is refused naming the file and the formats
// read: Debian 12's OpenEXR 3.1 allocates what a header claims before checking it.
TEST(ImageDecode, OpenExrIsRefusedWithItsReason) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("decode_" + std::to_string(::getpid()) + ".exr");
  {
    Imf::Array2D<Imf::Rgba> texels(1, 2);
    texels[0][0] = Imf::Rgba(2.5f, 0.5f, 0.125f, 1.0f);
    texels[0][1] = Imf::Rgba(0.0f, 4.0f, 1.0f, 0.5f);
    Imf::RgbaOutputFile file(path.c_str(), 2, 1, Imf::WRITE_RGBA);
    file.setFrameBuffer(&texels[0][0], 1, 2);
    file.writePixels(1);
  }
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  try {
    decodeImage(bytes.data(), bytes.size(), "env.exr", 1 << 20);
    ADD_FAILURE() << "an OpenEXR file was decoded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("env.exr"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Radiance HDR"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rad
