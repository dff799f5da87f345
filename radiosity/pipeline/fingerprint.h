#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/scene/environment_map.h"
#include "radiosity/scene/lights.h"
#include "radiosity/scene/scene.h"

namespace rad {

// FNV-1a over the bytes of everything fed to it: what a saved solution or kept form factors were
// made from, to tell whether a later scene and options still match them.
class Fingerprint {
 public:
  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    addBytes(&value, sizeof(T));
  }
  void add(const std::string& s) {
    add(s.size());
    addBytes(s.data(), s.size());
  }
  void add(const Rgb& c) {
    add(c.r);
    add(c.g);
    add(c.b);
  }
  std::string hex() const {
    std::ostringstream out;
    out << std::hex << hash_;
    return out.str();
  }

 private:
  void addBytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) hash_ = (hash_ ^ p[i]) * 0x100000001b3ull;
  }
  uint64_t hash_ = 0xcbf29ce484222325ull;
};

// The scene's geometry: positions, and each polygon's material, back-side link, corners and
// texture coordinates (which decide the textured reflectance and the cut-outs' holes).
inline void addGeometry(Fingerprint& f, const Scene& scene) {
  f.add(scene.positions.size());
  for (const Eigen::Vector3d& p : scene.positions)
    for (int k = 0; k < 3; ++k) f.add(p[k]);
  f.add(scene.polygons.size());
  for (const ScenePolygon& poly : scene.polygons) {
    f.add(poly.material);
    f.add(poly.backSideOf);
    f.add(poly.vertices.size());
    for (int v : poly.vertices) f.add(v);
    f.add(poly.uvs.size());
    for (const Eigen::Vector2d& uv : poly.uvs) {
      f.add(uv.x());
      f.add(uv.y());
    }
  }
}

// The scene's textures: each one's size and texels.
inline void addTextures(Fingerprint& f, const Scene& scene) {
  f.add(scene.textures.size());
  for (const Texture& t : scene.textures) {
    f.add(t.width);
    f.add(t.height);
    for (float v : t.rgba) f.add(v);
  }
}

// The lights: their kind, placement, shape and strength, an environment's texels included.
inline void addLights(Fingerprint& f, const std::vector<Light>& lights) {
  f.add(lights.size());
  for (const Light& l : lights) {
    f.add(static_cast<int>(l.type));
    for (const Eigen::Vector3d* v : {&l.position, &l.direction, &l.up})
      for (int k = 0; k < 3; ++k) f.add((*v)[k]);
    f.add(l.intensity);
    f.add(l.irradiance);
    f.add(l.radiance);
    f.add(l.cosOuter);
    f.add(l.cosInner);
    f.add(l.angularDiameterDegrees);
    f.add(static_cast<int>(l.skyModel));
    f.add(l.map ? l.map->width() : 0);
    f.add(l.map ? l.map->height() : 0);
    if (l.map)
      for (const Rgb& t : l.map->texels()) f.add(t);
  }
}

}  // namespace rad
