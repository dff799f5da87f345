// BMP (every variant) and TIFF through OpenImageIO, what Blender reads images with. Only these two
// of its readers are reached (image_decode.cpp picks them by the file's first bytes): Debian 12's
// OpenImageIO 2.4 hung on a malformed DDS and its OpenEXR 3.1 allocated 1.9 GB for a 56-byte
// header under fuzz_texture_image, so those formats stay refused.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <memory>

#include "radiosity/scene/image_decoders.h"

namespace rad::image_decoders {
namespace {

bool isFloatFormat(OIIO::TypeDesc format) {
  return format.basetype == OIIO::TypeDesc::FLOAT || format.basetype == OIIO::TypeDesc::HALF ||
         format.basetype == OIIO::TypeDesc::DOUBLE;
}

// Expands `channels` values per texel (grey, grey + alpha, RGB, RGBA; alpha where the file says)
// to RGBA, alpha `opaque` where the file has none.
template <typename T>
std::vector<T> toRgba(const std::vector<T>& in, std::size_t texels, int channels, int alphaChannel,
                      T opaque) {
  std::vector<T> out(texels * 4);
  const bool hasAlpha = alphaChannel >= 0 && alphaChannel < channels;
  const int colours = hasAlpha ? channels - 1 : channels;
  for (std::size_t t = 0; t < texels; ++t) {
    const T* texel = &in[t * channels];
    T colour[3] = {};
    for (int c = 0, k = 0; c < channels && k < 3; ++c)
      if (c != alphaChannel) colour[k++] = texel[c];
    if (colours == 1) colour[1] = colour[2] = colour[0];  // grey
    T* rgba = &out[t * 4];
    std::copy(colour, colour + 3, rgba);
    rgba[3] = hasAlpha ? texel[alphaChannel] : opaque;
  }
  return out;
}

}  // namespace

std::string decodeWithOpenImageIO(const char* reader, const unsigned char* bytes, std::size_t size,
                                  const SizeCheck& refuseSize, DecodedImage& image) {
  OIIO::Filesystem::IOMemReader memory(bytes, size);
  OIIO::ImageSpec config;
  // Colours as stored, alpha beside them: the texture look-ups treat alpha as coverage.
  config.attribute("oiio:UnassociatedAlpha", 1);
  // The bytes in memory (a glTF's embedded images have no file); the reader takes the proxy from
  // the configuration it is opened with.
  OIIO::Filesystem::IOProxy* proxy = &memory;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(reader, false, &config, &memory);
  if (!in) return "not a readable image: " + OIIO::geterror();
  OIIO::ImageSpec spec;
  if (!in->open(reader, spec, config)) return "not a readable image: " + in->geterror();
  if (spec.depth > 1) return "a volume image (depth " + std::to_string(spec.depth) + ") refused";
  const std::string refused = refuseSize(spec.width, spec.height);
  if (!refused.empty()) return refused;
  const int channels = std::min(spec.nchannels, 4);
  if (channels < 1) return "an image without channels";
  const int alpha = spec.alpha_channel < channels ? spec.alpha_channel : -1;
  const std::size_t texels = static_cast<std::size_t>(spec.width) * spec.height;
  if (isFloatFormat(spec.format)) {
    std::vector<float> values(texels * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, values.data()))
      return "corrupt image: " + in->geterror();
    image.rgbaFloat = toRgba(values, texels, channels, alpha, 1.0f);
  } else {
    std::vector<unsigned char> values(texels * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, values.data()))
      return "corrupt image: " + in->geterror();
    image.rgba8 = toRgba(values, texels, channels, alpha, static_cast<unsigned char>(255));
  }
  image.width = spec.width;
  image.height = spec.height;
  return {};
}

}  // namespace rad::image_decoders
