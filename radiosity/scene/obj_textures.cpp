#include "radiosity/scene/obj_textures.h"

#include <filesystem>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"

namespace rad {

int ObjTextureLoader::colour(const TextureMapStatement& map) { return load(map, false); }

int ObjTextureLoader::coverage(const TextureMapStatement& map) { return load(map, true); }

int ObjTextureLoader::load(const TextureMapStatement& map, bool coverage) {
  std::error_code ec;
  std::filesystem::path key = std::filesystem::weakly_canonical(map.path, ec);
  if (ec) key = map.path;
  const auto found = index_.find({key.string(), coverage});
  if (found != index_.end()) return found->second;

  int index = -1;
  try {
    textures_->push_back(read(map, coverage));
    index = static_cast<int>(textures_->size()) - 1;
  } catch (const InputError& e) {
    if (unreadable_ == UnreadableTextures::Refuse) throw;
    logWarning(std::string(e.what()) +
               ": using the material's own colour instead (--strict makes this an error)");
    fallbacks_->push_back(e.what());
  }
  index_.emplace(std::make_pair(key.string(), coverage), index);  // warned once per file
  return index;
}

Texture ObjTextureLoader::read(const TextureMapStatement& map, bool coverage) const {
  // Only a regular file: a device or a pipe named by mistake (or by a fuzzer) would never end.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(map.path, ec))
    throw InputError(map.file, map.line, "texture: " + map.path + ": cannot open the texture file");
  Texture texture;
  try {
    texture = loadTextureFile(map.path, coverage ? TextureEncoding::Linear : TextureEncoding::Srgb);
  } catch (const InputError& e) {
    // The user fixes the MTL statement (or the file it names): point at both.
    throw InputError(map.file, map.line, std::string("texture: ") + e.what());
  }
  if (coverage && !hasTransparentTexel(texture)) {
    for (std::size_t i = 0; i < texture.rgba.size(); i += 4)
      texture.rgba[i + 3] = (texture.rgba[i] + texture.rgba[i + 1] + texture.rgba[i + 2]) / 3;
  }
  logDebug("texture " + map.path + ": " + std::to_string(texture.width) + "×" +
           std::to_string(texture.height) + " texels");
  return texture;
}

bool hasTransparentTexel(const Texture& texture) {
  for (std::size_t i = 3; i < texture.rgba.size(); i += 4)
    if (texture.rgba[i] < 1) return true;
  return false;
}

}  // namespace rad
