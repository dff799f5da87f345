#include "radiosity/output/vertex_colors_ply.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <limits>
#include <sstream>
#include <string>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// Little-endian regardless of the host: the bytes are taken from the value, not from memory.
void putU32(std::string& buffer, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) buffer.push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}
void putFloat(std::string& buffer, double v) {
  const float f = static_cast<float>(v);
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  putU32(buffer, bits);
}
void putInt(std::string& buffer, int v) { putU32(buffer, static_cast<std::uint32_t>(v)); }

}  // namespace

std::vector<Rgb> interpolateVertexRadiance(const VertexInterpolation& interpolation,
                                           const std::vector<Rgb>& radiosityPerElement) {
  std::vector<Eigen::Vector3d> perElement(radiosityPerElement.size());
  for (size_t e = 0; e < radiosityPerElement.size(); ++e) {
    const Rgb& b = radiosityPerElement[e];
    perElement[e] = Eigen::Vector3d(b.r, b.g, b.b);
  }
  const std::vector<Eigen::Vector3d> perVertex = interpolation.interpolate(perElement);
  std::vector<Rgb> radiance(perVertex.size());
  // Lambertian: radiance is the same in every direction, B = π·L.
  for (size_t v = 0; v < perVertex.size(); ++v)
    radiance[v] = Rgb(perVertex[v].x(), perVertex[v].y(), perVertex[v].z()) / M_PI;
  return radiance;
}

std::vector<Rgb> interpolateVertexRadiance(
    const VertexInterpolation& interpolation, const std::vector<Rgb>& radiosityPerElement,
    const std::vector<std::array<Rgb, 3>>& radiosityAtPoints) {
  if (radiosityAtPoints.empty())
    return interpolateVertexRadiance(interpolation, radiosityPerElement);
  std::vector<std::array<Eigen::Vector3d, 3>> corners(radiosityAtPoints.size());
  for (size_t e = 0; e < corners.size(); ++e) {
    std::array<Eigen::Vector3d, 3> g;
    for (int k = 0; k < 3; ++k) {
      const Rgb& b = radiosityAtPoints[e][k];
      g[k] = Eigen::Vector3d(b.r, b.g, b.b);
    }
    corners[e] = linearAtCorners(g);
  }
  const std::vector<Eigen::Vector3d> perVertex = interpolation.interpolateCorners(corners);
  std::vector<Rgb> radiance(perVertex.size());
  for (size_t v = 0; v < perVertex.size(); ++v) {
    const Eigen::Vector3d b = perVertex[v].cwiseMax(0.0);  // no negative light past a shadow edge
    radiance[v] = Rgb(b.x(), b.y(), b.z()) / M_PI;
  }
  return radiance;
}

void writeVertexColorsPly(std::ostream& out, const VertexInterpolation& interpolation,
                          const PatchMesh& mesh, const std::vector<Rgb>& radianceVertex,
                          const ToneMap& toneMap) {
  const int vertexCount = interpolation.vertexCount();
  const int faceCount = mesh.elementCount();
  RAD_CHECK_EQ(radianceVertex.size(), vertexCount);

  // Header in its own stream so the caller's formatting state is left alone.
  std::ostringstream header;
  header.precision(std::numeric_limits<double>::max_digits10);
  header << "ply\n"
         << "format binary_little_endian 1.0\n"
         << "comment radiosity solver baked vertex colours\n"
         << "comment radiance_r radiance_g radiance_b: outgoing radiance L = B/pi, "
            "W m^-2 sr^-1, linear\n"
         << "comment red green blue: 8-bit sRGB of clamp(exposure * radiance, 0, 1)\n"
         << "comment exposure " << toneMap.exposure << "\n"
         << "element vertex " << vertexCount << "\n"
         << "property float x\nproperty float y\nproperty float z\n"
         << "property float nx\nproperty float ny\nproperty float nz\n"
         << "property float radiance_r\nproperty float radiance_g\nproperty float radiance_b\n"
         << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
         << "element face " << faceCount << "\n"
         << "property list uchar int vertex_indices\n"
         << "end_header\n";
  out << header.str();

  // The body goes out in chunks: a million-element scene would otherwise need one 50 MB buffer.
  constexpr size_t kChunk = size_t{1} << 20;
  std::string body;
  body.reserve(kChunk + 64);
  const auto flushIfFull = [&](bool force) {
    if (body.size() >= kChunk || (force && !body.empty())) {
      out.write(body.data(), static_cast<std::streamsize>(body.size()));
      body.clear();
    }
  };
  for (int v = 0; v < vertexCount; ++v) {
    const Eigen::Vector3d& p = interpolation.position(v);
    const Eigen::Vector3d& n = interpolation.normal(v);
    const Rgb& l = radianceVertex[v];
    for (int k = 0; k < 3; ++k) putFloat(body, p[k]);
    for (int k = 0; k < 3; ++k) putFloat(body, n[k]);
    for (int k = 0; k < 3; ++k) putFloat(body, l[k]);
    for (std::uint8_t c : toneMap.toSrgb8(l)) body.push_back(static_cast<char>(c));
    flushIfFull(false);
  }
  for (int e = 0; e < faceCount; ++e) {
    body.push_back(static_cast<char>(3));
    for (int v : interpolation.triangle(e)) putInt(body, v);
    flushIfFull(false);
  }
  flushIfFull(true);
}

}  // namespace rad
