#pragma once

#include <cstdint>

namespace rad {

// SplitMix64 finaliser: mixes a 64-bit key into a well-distributed value. Used to derive
// independent, reproducible streams from (seed, element, ...) without any shared state, so the
// results do not depend on thread count or scheduling.
inline uint64_t mix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

inline uint64_t streamKey(uint64_t seed, uint64_t a, uint64_t b = 0) {
  return mix64(seed ^ mix64(a ^ mix64(b + 0x632be59bd9b4e019ull)));
}

// PCG32 (O'Neill 2014): small, fast, statistically sound.
class Rng {
 public:
  explicit Rng(uint64_t key, uint64_t stream = 0) {
    inc_ = (stream << 1u) | 1u;
    state_ = 0;
    next();
    state_ += key;
    next();
  }
  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
  }
  // Uniform in [0, 1), never 1.
  double uniform() { return next53(); }
  uint32_t below(uint32_t n) {  // uniform integer in [0, n), unbiased
    const uint32_t threshold = (-n) % n;
    for (;;) {
      const uint32_t r = next();
      if (r >= threshold) return r % n;
    }
  }

 private:
  double next53() {
    const uint64_t hi = next() >> 5, lo = next() >> 6;
    return (static_cast<double>(hi) * 67108864.0 + static_cast<double>(lo)) *
           (1.0 / 9007199254740992.0);
  }
  uint64_t state_ = 0, inc_ = 1;
};

}  // namespace rad
