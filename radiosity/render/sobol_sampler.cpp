#include "radiosity/render/sobol_sampler.h"

#include <array>

#include "radiosity/core/stream_tags.h"

namespace rad {
namespace {

uint32_t reverseBits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Nested uniform (Owen) scramble of a 32-bit binary fraction: each bit is flipped by a hash of
// the bits above it. Vegdahl's improved Laine–Karras hash works on the reversed bits, where a
// multiplication carries information only from lower to higher bits. This is the hash on the
// reversed bits: owenScramble(x) = reverseBits(laineKarras(reverseBits(x))), and point() keeps its
// values reversed where the next step wants them so that it reverses 4 times instead of 7.
uint32_t laineKarras(uint32_t x, uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

// Generator matrix of Sobol's second dimension (primitive polynomial x + 1): column k is
// v_k = v_{k−1} xor (v_{k−1} >> 1), v_0 = 1/2. The first dimension is the van der Corput
// radical inverse (the bit reversal of the index). The product matrix × index is the xor of the
// columns of the index's set bits; it is done a byte at a time from tables rather than a bit at a
// time, which took a third of a final-gather render. The tables give the product bit-reversed
// (table[j][b]: the reversed xor of the columns 8j… of byte value b), as the scramble takes it.
const std::array<std::array<uint32_t, 256>, 4>& sobolSecondDimensionReversed() {
  static const std::array<std::array<uint32_t, 256>, 4> tables = [] {
    std::array<uint32_t, 32> v{};
    v[0] = 1u << 31;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    std::array<std::array<uint32_t, 256>, 4> t{};
    for (int j = 0; j < 4; ++j)
      for (uint32_t b = 0; b < 256; ++b)
        for (int k = 0; k < 8; ++k)
          if (b & (1u << k)) t[j][b] ^= reverseBits(v[8 * j + k]);
    return t;
  }();
  return tables;
}

constexpr double kTwoToMinus32 = 1.0 / 4294967296.0;

}  // namespace

SobolSampler::SobolSampler(uint64_t seed, uint64_t pixel, Rng& rng)
    : pixelKey_(streamKey(seed, pixel, stream_tag::kSobolPixel)), rng_(rng) {}

void SobolSampler::startSample(int index) {
  sample_ = index;
  dimension_ = 0;
}

Point2 SobolSampler::point(uint32_t index, uint64_t key) {
  const uint64_t a = mix64(key), b = mix64(key ^ 0x9e3779b97f4a7c15ull);
  // Scrambling the index (as a fraction) permutes the sequence by aligned blocks: the first 2^m
  // indices go to one aligned block of 2^m Sobol points, which is again a (0,m,2)-net.
  // i: the scrambled index; the first dimension's value is reverseBits(i), whose scramble
  // reverses it back.
  const uint32_t i = reverseBits(laineKarras(reverseBits(index), static_cast<uint32_t>(a)));
  const auto& t = sobolSecondDimensionReversed();
  const uint32_t yReversed =
      t[0][i & 0xffu] ^ t[1][(i >> 8) & 0xffu] ^ t[2][(i >> 16) & 0xffu] ^ t[3][i >> 24];
  return {reverseBits(laineKarras(i, static_cast<uint32_t>(a >> 32))) * kTwoToMinus32,
          reverseBits(laineKarras(yReversed, static_cast<uint32_t>(b))) * kTwoToMinus32};
}

Point2 SobolSampler::get2D() {
  return point(static_cast<uint32_t>(sample_), pixelKey_ + dimension_++);
}

void SobolSampler::get2DArray(int count, std::vector<Point2>& out) {
  out.resize(count);
  const uint64_t key = pixelKey_ + dimension_++;
  const uint32_t base = static_cast<uint32_t>(sample_) * static_cast<uint32_t>(count);
  for (int k = 0; k < count; ++k) out[k] = point(base + static_cast<uint32_t>(k), key);
}

}  // namespace rad
