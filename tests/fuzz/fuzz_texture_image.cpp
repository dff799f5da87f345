// libFuzzer target: image bytes through decodeTexture() (radiosity/scene/texture.h: libpng,
// libjpeg-turbo, OpenImageIO for BMP and TIFF, stb_image for TGA and HDR),
// as an MTL's map_Kd/map_Ke/map_d file or an image embedded in a .glb reaches it, in both
// encodings. An image it accepts must have its stated size, finite non-negative values (alpha in
// [0, 1]), and give finite look-ups and area averages.
// Findings: crashes, sanitizer reports, and any exception other than InputError.
// Images are capped at 2^18 texels here: a 16 KB input may claim 2^26 texels, which a decoder fills
// (padding the missing rows) in seconds under the sanitizers; the cap itself is tested in
// test_texture.cpp, and the fuzzer's time is better spent on the decoders' many small images.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "radiosity/core/errors.h"
#include "radiosity/scene/texture.h"

namespace {

constexpr long long kMaxFuzzTexels = 1LL << 18;

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "fuzz_texture_image: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (rad::TextureEncoding encoding : {rad::TextureEncoding::Srgb, rad::TextureEncoding::Linear}) {
    rad::Texture t;
    try {
      t = rad::decodeTexture(data, size, "fuzz.img", encoding, kMaxFuzzTexels);
    } catch (const rad::InputError&) {
      return 0;
    }
    check(t.width > 0 && t.height > 0 &&
              t.rgba.size() == static_cast<std::size_t>(t.width) * t.height * 4,
          "an accepted image has the wrong number of values");
    for (std::size_t i = 0; i < t.rgba.size(); ++i)
      check(std::isfinite(t.rgba[i]) && t.rgba[i] >= 0 && (i % 4 != 3 || t.rgba[i] <= 1),
            "an accepted image holds a non-finite, negative or out-of-range value");
    const rad::Rgb c = t.colour({0.3, 0.7});
    const std::array<Eigen::Vector2d, 3> small{{{0.1, 0.1}, {0.4, 0.2}, {0.2, 0.5}}},
        large{{{-3, -2}, {5, -1}, {0, 7}}};
    const rad::Rgb a = t.averageColour(small), b = t.averageColour(large);
    check(c.isFinite() && a.isFinite() && b.isFinite() && std::isfinite(t.averageAlpha(small)),
          "a look-up or an average is not finite");
  }
  return 0;
}
