#include "radiosity/app/baked_materials.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "radiosity/core/image.h"
#include "radiosity/output/image_io.h"

namespace rad {
namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

EncodedImage encodeTexture(const Texture& texture) {
  EncodedImage image;
  image.name = std::filesystem::path(texture.source).stem().string();
  const std::string ext = lowerExtension(texture.source);
  // A file glTF can hold as it is (an image embedded in a .glb has a "#" source: re-encoded).
  if ((ext == ".png" || ext == ".jpg" || ext == ".jpeg") &&
      texture.source.find('#') == std::string::npos) {
    std::ifstream in(texture.source, std::ios::binary);
    image.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.good() || in.eof()) {
      image.mimeType = ext == ".png" ? "image/png" : "image/jpeg";
      if (!image.bytes.empty()) return image;
    }
  }
  // Exposure 1 is the sRGB encoding of the linear texels themselves (clamped to [0, 1]).
  ImageRgb rgb(texture.width, texture.height);
  for (size_t i = 0; i < rgb.pixels.size(); ++i)
    rgb.pixels[i] = Rgb(texture.rgba[4 * i], texture.rgba[4 * i + 1], texture.rgba[4 * i + 2]);
  image.mimeType = "image/png";
  image.bytes = encodePng(rgb, ToneMap{1.0});
  return image;
}

}  // namespace

BakedLook bakedBaseColours(const Scene& scene, bool textureUvs) {
  BakedLook look;
  std::vector<int> imageOfTexture(scene.textures.size(), -1);
  for (const Material& m : scene.materials) {
    BaseColour base;
    base.factor = m.diffuse;
    if (textureUvs && m.diffuseTexture >= 0) {
      int& image = imageOfTexture[m.diffuseTexture];
      if (image < 0) {
        image = static_cast<int>(look.images.size());
        look.images.push_back(encodeTexture(scene.textures[m.diffuseTexture]));
      }
      base.image = image;
    }
    look.baseColours.push_back(base);
  }
  return look;
}

}  // namespace rad
