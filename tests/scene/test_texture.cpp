// Image textures: the sRGB decoding of 8-bit colour maps, the v-up look-up with repeat wrap, the
// area average over a UV triangle, and the errors for missing and corrupt files.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/scene/texture.h"

namespace rad {
namespace {

// An uncompressed true-colour TGA (type 2, 24 bit, rows bottom first as TGA's default), built
// byte by byte so the test depends on no encoder. `rgb` holds rows top first.
std::vector<unsigned char> tga(int w, int h, const std::vector<unsigned char>& rgb) {
  std::vector<unsigned char> out = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  out.push_back(w & 255), out.push_back(w >> 8), out.push_back(h & 255), out.push_back(h >> 8);
  out.push_back(24), out.push_back(0);
  for (int y = h - 1; y >= 0; --y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = &rgb[(y * w + x) * 3];
      out.push_back(p[2]), out.push_back(p[1]), out.push_back(p[0]);  // BGR
    }
  return out;
}

// The message of the InputError that decoding `bytes` as `name` throws; a test failure (and "")
// when it decodes.
std::string decodeErrorOf(const std::vector<unsigned char>& bytes, const std::string& name) {
  try {
    decodeTexture(bytes.data(), bytes.size(), name, TextureEncoding::Srgb);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << name << " decoded without an error";
  return "";
}

TEST(Texture, SrgbColourMapsDecodeToLinearAndDataMapsDoNot) {
  const auto bytes = tga(2, 1, {0, 188, 255, 255, 255, 255});
  const Texture srgb = decodeTexture(bytes.data(), bytes.size(), "t.tga", TextureEncoding::Srgb);
  ASSERT_EQ(srgb.width, 2);
  ASSERT_EQ(srgb.height, 1);
  // Texel (0, 0): r 0, g 188 (sRGB 0.737 → linear 0.5029), b 1; alpha 1 (the file has none).
  EXPECT_NEAR(srgb.rgba[0], 0.0, 1e-7);
  EXPECT_NEAR(srgb.rgba[1], std::pow((188 / 255.0 + 0.055) / 1.055, 2.4), 1e-6);
  EXPECT_NEAR(srgb.rgba[2], 1.0, 1e-7);
  EXPECT_NEAR(srgb.rgba[3], 1.0, 1e-7);
  const Texture linear =
      decodeTexture(bytes.data(), bytes.size(), "t.tga", TextureEncoding::Linear);
  EXPECT_NEAR(linear.rgba[1], 188 / 255.0, 1e-6);
}

TEST(Texture, VPointsUpAndCoordinatesRepeat) {
  // Top row red, bottom row blue: v near 1 is the top.
  const auto bytes = tga(1, 2, {255, 0, 0, 0, 0, 255});
  const Texture t = decodeTexture(bytes.data(), bytes.size(), "t.tga", TextureEncoding::Linear);
  EXPECT_NEAR(t.colour({0.5, 0.75}).r, 1.0, 1e-9);
  EXPECT_NEAR(t.colour({0.5, 0.25}).b, 1.0, 1e-9);
  EXPECT_NEAR(t.colour({7.5, -2.75}).b, 1.0, 1e-9);  // one period is one texture
  // Half-way between the texel centres the bilinear look-up mixes them equally.
  EXPECT_NEAR(t.colour({0.5, 0.5}).r, 0.5, 1e-9);
}

TEST(Texture, TriangleAverageIsTheAreaWeightedMeanOfTheTexelsItCovers) {
  // A 2×2 checker of 0 and 1: any triangle covering whole periods averages 0.5; a triangle inside
  // one texel is that texel.
  const auto bytes = tga(2, 2, {255, 255, 255, 0, 0, 0, 0, 0, 0, 255, 255, 255});
  const Texture t = decodeTexture(bytes.data(), bytes.size(), "t.tga", TextureEncoding::Linear);
  EXPECT_NEAR(t.averageColour({{{0, 0}, {4, 0}, {0, 4}}}).g, 0.5, 0.02);
  // The lower-left texel (u, v in [0, 0.5)) is row 1 (bottom), column 0: black.
  EXPECT_NEAR(t.averageColour({{{0.1, 0.1}, {0.2, 0.1}, {0.1, 0.2}}}).g, 0.0, 0.05);
  // Upper-left texel: white.
  EXPECT_NEAR(t.averageColour({{{0.1, 0.8}, {0.2, 0.8}, {0.1, 0.9}}}).g, 1.0, 0.05);
}

TEST(Texture, MissingAndCorruptFilesNameTheFile) {
  try {
    loadTextureFile("/nonexistent/wood.png", TextureEncoding::Srgb);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/wood.png"), std::string::npos);
  }
  const std::vector<unsigned char> garbage = {0x89, 'P', 'N', 'G', 13, 10, 26, 10, 0, 0, 0};
  try {
    decodeTexture(garbage.data(), garbage.size(), "broken.png", TextureEncoding::Srgb);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.png"), std::string::npos) << e.what();
  }
}

TEST(Texture, AHeaderClaimingMoreTexelsThanTheCapIsRefusedBeforeDecoding) {
  // A TGA header stating 8192 × 8193 texels followed by no pixel data at all: the default cap
  // (8192²) refuses it from the header alone, before the size-per-byte check, naming the file and
  // the size it claims.
  const std::vector<unsigned char> header = {0, 0, 2, 0, 0,  0, 0,  0,  0,
                                             0, 0, 0, 0, 32, 1, 32, 24, 0};
  const std::string huge = decodeErrorOf(header, "huge.tga");
  EXPECT_NE(huge.find("huge.tga"), std::string::npos) << huge;
  EXPECT_NE(huge.find("8192×8193"), std::string::npos) << huge;
  // A header whose size its data cannot hold: 1000 × 1000 texels in 18 bytes.
  const std::vector<unsigned char> truncated = {0, 0, 2, 0,    0, 0,    0, 0,  0,
                                                0, 0, 0, 0xe8, 3, 0xe8, 3, 24, 0};
  const std::string cut = decodeErrorOf(truncated, "cut.tga");
  EXPECT_NE(cut.find("cut.tga"), std::string::npos) << cut;
  EXPECT_NE(cut.find("corrupt header"), std::string::npos) << cut;
  // A caller's smaller cap applies in the same way; an image within it decodes.
  const auto small = tga(2, 2, std::vector<unsigned char>(12, 128));
  EXPECT_THROW(decodeTexture(small.data(), small.size(), "s.tga", TextureEncoding::Srgb, 3),
               InputError);
  EXPECT_EQ(decodeTexture(small.data(), small.size(), "s.tga", TextureEncoding::Srgb, 4).width, 2);
}

}  // namespace
}  // namespace rad
