#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// How an image file's 8-bit values map to linear values. Colour maps (map_Kd, map_Ke,
// baseColorTexture, emissiveTexture) are sRGB-encoded; data maps (map_d, an alpha channel) and
// HDR files (.hdr: already linear floats) are not.
enum class TextureEncoding { Srgb, Linear };

// A decoded image in linear values: RGBA per texel, rows top first (as image files store them).
// Texture coordinates follow OBJ and OpenGL: u to the right, v up, (0, 0) the bottom-left
// corner; both wrap (repeat). A glTF reader flips its v (glTF's origin is top-left) on input.
struct Texture {
  std::string source;  // the file it came from, or "<file>#/images/<i>" for an embedded image
  int width = 0, height = 0;
  std::vector<float> rgba;  // width·height·4 linear values; alpha 1 where the file has none

  // Bilinear look-up with repeat wrap.
  Rgb colour(const Eigen::Vector2d& uv) const;
  double alpha(const Eigen::Vector2d& uv) const;
  // Area average over the UV triangle (a, b, c), sampled so each texel it covers counts: what an
  // element whose corners map to a, b, c reflects on average.
  Rgb averageColour(const std::array<Eigen::Vector2d, 3>& uv) const;
  double averageAlpha(const std::array<Eigen::Vector2d, 3>& uv) const;

 private:
  std::array<double, 4> texel(int x, int y) const;
  std::array<double, 4> bilinear(const Eigen::Vector2d& uv) const;
  std::array<double, 4> average(const std::array<Eigen::Vector2d, 3>& uv) const;
};

// Reads PNG, JPEG, TGA, BMP (8-bit, decoded per `encoding`) or Radiance HDR (linear floats).
// Throws InputError naming `path` when the file is missing, unreadable or not an image.
Texture loadTextureFile(const std::string& path, TextureEncoding encoding);
// The same from bytes in memory (an image embedded in a .glb); `source` names it in errors.
// Images of more than `maxTexels` texels are refused before decoding (a corrupt header must not
// allocate gigabytes); the default, 2^26 (8192², 1 GiB as float RGBA), fits any real texture.
constexpr long long kMaxTextureTexels = 1LL << 26;
Texture decodeTexture(const unsigned char* bytes, std::size_t size, const std::string& source,
                      TextureEncoding encoding, long long maxTexels = kMaxTextureTexels);

// The sRGB transfer function's inverse (IEC 61966-2-1): an 8-bit colour value / 255 to linear.
double srgbToLinear(double encoded);

}  // namespace rad
