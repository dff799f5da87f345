#include "radiosity/scene/texture.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>

#include "radiosity/core/errors.h"
#include "radiosity/scene/image_decode.h"

namespace rad {
namespace {

int wrap(int i, int n) {
  const int m = i % n;
  return m < 0 ? m + n : m;
}

// Footprints spanning up to this many texel cells (bounding box) are averaged exactly, by
// clipping the triangle to each cell; larger ones are sampled (an element over many texels barely
// depends on how the few along its edges are split).
constexpr double kExactCells = 256;

// Area of the convex polygon `p` clipped to the cell [x, x+1] × [y, y+1] (Sutherland–Hodgman).
double areaInCell(std::vector<Eigen::Vector2d> p, double x, double y) {
  auto clip = [&](int axis, double bound, bool keepBelow) {
    std::vector<Eigen::Vector2d> out;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Eigen::Vector2d &a = p[i], &b = p[(i + 1) % p.size()];
      const bool inA = keepBelow ? a[axis] <= bound : a[axis] >= bound;
      const bool inB = keepBelow ? b[axis] <= bound : b[axis] >= bound;
      if (inA) out.push_back(a);
      if (inA != inB) out.push_back(a + (b - a) * ((bound - a[axis]) / (b[axis] - a[axis])));
    }
    p = std::move(out);
  };
  clip(0, x, false), clip(0, x + 1, true), clip(1, y, false), clip(1, y + 1, true);
  double twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &a = p[i], &b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace

double srgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

std::array<double, 4> Texture::texel(int x, int y) const {
  const std::size_t i = (static_cast<std::size_t>(wrap(y, height)) * width + wrap(x, width)) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

std::array<double, 4> Texture::bilinear(const Eigen::Vector2d& uv) const {
  // Texel centres sit at half-integers; v up means row 0 (the top) is v = 1.
  const double x = uv.x() * width - 0.5, y = (1.0 - uv.y()) * height - 0.5;
  if (!std::isfinite(x) || !std::isfinite(y)) return texel(0, 0);
  const double fx = std::floor(x), fy = std::floor(y);
  // Reduce to one period first so huge coordinates keep their precision as ints.
  const int x0 = static_cast<int>(std::fmod(fx, width)),
            y0 = static_cast<int>(std::fmod(fy, height));
  const double tx = x - fx, ty = y - fy;
  const auto a = texel(x0, y0), b = texel(x0 + 1, y0), c = texel(x0, y0 + 1),
             d = texel(x0 + 1, y0 + 1);
  std::array<double, 4> out{};
  for (int k = 0; k < 4; ++k)
    out[k] = (1 - ty) * ((1 - tx) * a[k] + tx * b[k]) + ty * ((1 - tx) * c[k] + tx * d[k]);
  return out;
}

Rgb Texture::colour(const Eigen::Vector2d& uv) const {
  const auto t = bilinear(uv);
  return {t[0], t[1], t[2]};
}

double Texture::alpha(const Eigen::Vector2d& uv) const { return bilinear(uv)[3]; }

std::array<double, 4> Texture::average(const std::array<Eigen::Vector2d, 3>& uv) const {
  // The image is taken as piecewise constant (each texel a little square), so the average is
  // the texels' values weighted by the area of the triangle over each: exact for small
  // footprints, else nearest look-ups.
  // The triangle's footprint in texels decides the sampling: split it into k² similar
  // sub-triangles (k along each edge) and take each one's centroid, about sixteen per texel
  // covered (1 to 4096 sub-triangles).
  const Eigen::Vector2d e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
  const double texels = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x()) * width * height;
  {
    // Texel space: x = u·width, y = (1 − v)·height, cell (i, j) the texel (i, j) wrapped.
    std::vector<Eigen::Vector2d> t;
    for (const Eigen::Vector2d& p : uv) t.emplace_back(p.x() * width, (1.0 - p.y()) * height);
    const Eigen::Vector2d lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]),
                          hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
    const double cells = (std::floor(hi.x()) - std::floor(lo.x()) + 1) *
                         (std::floor(hi.y()) - std::floor(lo.y()) + 1);
    if (texels > 0 && lo.allFinite() && hi.allFinite() && cells <= kExactCells) {
      // Shift to the first period so the cell indices stay small.
      const Eigen::Vector2d shift(std::floor(lo.x() / width) * width,
                                  std::floor(lo.y() / height) * height);
      for (Eigen::Vector2d& p : t) p -= shift;
      std::array<double, 4> sum{};
      double area = 0;
      for (int y = static_cast<int>(std::floor(lo.y() - shift.y()));
           y <= static_cast<int>(std::floor(hi.y() - shift.y())); ++y)
        for (int x = static_cast<int>(std::floor(lo.x() - shift.x()));
             x <= static_cast<int>(std::floor(hi.x() - shift.x())); ++x) {
          const double a = areaInCell(t, x, y);
          if (!(a > 0)) continue;
          const auto v = texel(x, y);
          for (int c = 0; c < 4; ++c) sum[c] += a * v[c];
          area += a;
        }
      if (area > 0) {
        for (double& s : sum) s /= area;
        return sum;
      }
    }
  }
  const int k = std::clamp(static_cast<int>(std::ceil(std::sqrt(16 * texels))), 1, 64);
  std::array<double, 4> sum{};
  int n = 0;
  auto add = [&](double a, double b) {  // barycentric (a, b) of uv[1], uv[2] in the triangle
    const Eigen::Vector2d p = uv[0] + a * e1 + b * e2;
    const double x = std::floor(std::fmod(p.x(), 1.0) * width),
                 y = std::floor((1.0 - std::fmod(p.y(), 1.0)) * height);
    const auto t = texel(std::isfinite(x) ? static_cast<int>(x) : 0,
                         std::isfinite(y) ? static_cast<int>(y) : 0);
    for (int c = 0; c < 4; ++c) sum[c] += t[c];
    ++n;
  };
  for (int i = 0; i < k; ++i)
    for (int j = 0; i + j < k; ++j) {
      add((i + 1.0 / 3) / k, (j + 1.0 / 3) / k);                     // upright
      if (i + j + 1 < k) add((i + 2.0 / 3) / k, (j + 2.0 / 3) / k);  // inverted
    }
  for (double& s : sum) s /= n;
  return sum;
}

Rgb Texture::averageColour(const std::array<Eigen::Vector2d, 3>& uv) const {
  const auto a = average(uv);
  return {a[0], a[1], a[2]};
}

double Texture::averageAlpha(const std::array<Eigen::Vector2d, 3>& uv) const {
  return average(uv)[3];
}

Texture decodeTexture(const unsigned char* bytes, std::size_t size, const std::string& source,
                      TextureEncoding encoding, long long maxTexels) {
  const DecodedImage image = decodeImage(bytes, size, source, maxTexels);
  Texture texture;
  texture.source = source;
  texture.width = image.width;
  texture.height = image.height;
  if (image.isFloat()) {
    texture.rgba = image.rgbaFloat;
  } else {
    float table[256];
    for (int i = 0; i < 256; ++i)
      table[i] = static_cast<float>(encoding == TextureEncoding::Srgb ? srgbToLinear(i / 255.0)
                                                                      : i / 255.0);
    texture.rgba.resize(image.rgba8.size());
    for (std::size_t i = 0; i < image.rgba8.size(); ++i)
      texture.rgba[i] = (i % 4 == 3) ? image.rgba8[i] / 255.0f : table[image.rgba8[i]];
  }
  for (float& v : texture.rgba)
    if (!std::isfinite(v) || v < 0) v = 0;  // HDR files can hold anything
  return texture;
}

Texture loadTextureFile(const std::string& path, TextureEncoding encoding) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the texture file");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  return decodeTexture(bytes.data(), bytes.size(), path, encoding);
}

}  // namespace rad
