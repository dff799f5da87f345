#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/scene/mtl_texture_map.h"
#include "radiosity/scene/scene.h"
#include "radiosity/scene/texture.h"

namespace rad {

// Loads the images an OBJ's materials name into a scene's texture list, each image once per use
// however many materials share it (a colour map is sRGB-decoded, a coverage map is not, so one
// file used both ways is two textures). A missing or unreadable image is an InputError at the
// MTL statement that names it, or with UseMaterialColour a warning saying so and an entry in
// `fallbacks`, and no texture (-1).
class ObjTextureLoader {
 public:
  ObjTextureLoader(std::vector<Texture>* textures, UnreadableTextures unreadable,
                   std::vector<std::string>* fallbacks)
      : textures_(textures), unreadable_(unreadable), fallbacks_(fallbacks) {}

  // `map_Kd` or `map_Ke`: sRGB colour (alpha kept). Returns the index into the texture list, or
  // -1 for an image not read (UseMaterialColour).
  int colour(const TextureMapStatement& map);
  // `map_d`: linear coverage in the alpha channel. An image with an alpha channel of its own
  // keeps it; otherwise its grey value (mean of the three channels) becomes the alpha.
  int coverage(const TextureMapStatement& map);

  int filesDecoded() const { return static_cast<int>(index_.size()); }

 private:
  int load(const TextureMapStatement& map, bool coverage);
  Texture read(const TextureMapStatement& map, bool coverage) const;

  std::vector<Texture>* textures_;
  UnreadableTextures unreadable_;
  std::vector<std::string>* fallbacks_;
  std::map<std::pair<std::string, bool>, int> index_;  // (canonical path, coverage) → texture
};

// Whether any texel is less than fully opaque: a colour map whose alpha then cuts out the surface.
bool hasTransparentTexel(const Texture& texture);

}  // namespace rad
