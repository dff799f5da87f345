#include "radiosity/scene/coverage.h"

#include <cstddef>

namespace rad {
namespace {

bool hasTransparentTexel(const Texture& texture) {
  for (std::size_t i = 3; i < texture.rgba.size(); i += 4)
    if (texture.rgba[i] < 1.0f) return true;
  return false;
}

}  // namespace

CoverageMap::CoverageMap(const Material& material, const std::vector<Texture>& textures)
    : cutoff_(material.alphaCutoff) {
  const int index = material.alphaTexture >= 0  ? material.alphaTexture
                    : material.alphaFromDiffuse ? material.diffuseTexture
                                                : -1;
  if (index < 0 || index >= static_cast<int>(textures.size())) return;
  texture_ = &textures[static_cast<std::size_t>(index)];
  // The diffuse texture's coverage is its alpha by definition; a map_d may be greyscale.
  alphaChannel_ = material.alphaTexture < 0 || hasTransparentTexel(*texture_);
}

double CoverageMap::at(const Eigen::Vector2d& uv) const {
  if (!texture_) return 1.0;
  return alphaChannel_ ? texture_->alpha(uv) : texture_->colour(uv).sum() / 3;
}

double CoverageMap::average(const std::array<Eigen::Vector2d, 3>& uv) const {
  if (!texture_) return 1.0;
  return alphaChannel_ ? texture_->averageAlpha(uv) : texture_->averageColour(uv).sum() / 3;
}

}  // namespace rad
