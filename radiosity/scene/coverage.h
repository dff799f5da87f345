#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "radiosity/scene/material.h"
#include "radiosity/scene/texture.h"

namespace rad {

// A material's cut-out mask: the coverage (1 solid, 0 a hole) at a texture coordinate, from its
// alphaTexture (map_d) or from the alpha of its diffuse texture (alphaFromDiffuse). The one place
// that decides which channel holds the coverage: the alpha channel when the image has one that
// is not all opaque, else the mean of its colour channels (a greyscale map_d).
class CoverageMap {
 public:
  // The material's mask; without cut-outs (or when its texture is missing) a map that covers
  // everywhere (hasHoles() false).
  CoverageMap(const Material& material, const std::vector<Texture>& textures);

  bool hasHoles() const { return texture_ != nullptr; }
  // Bilinear coverage at `uv` (v up, repeat wrap, as Texture).
  double at(const Eigen::Vector2d& uv) const;
  // Whether a ray hitting the surface at `uv` stops there: coverage at or above the cutoff.
  bool stopsRayAt(const Eigen::Vector2d& uv) const { return !hasHoles() || at(uv) >= cutoff_; }
  // Area average over the UV triangle: the fraction of an element that holds material, which
  // scales its reflectance and emission in the radiosity pass.
  double average(const std::array<Eigen::Vector2d, 3>& uv) const;

 private:
  const Texture* texture_ = nullptr;
  bool alphaChannel_ = true;
  double cutoff_ = 0.5;
};

}  // namespace rad
