#pragma once

// The tags that keep the project's random streams apart: every stream is
// streamKey(seed, tag, ...) or streamKey(seed ^ tag, ...) (core/rng.h), so two estimators that
// share a seed and an element, texel or pixel still draw independent numbers. One list, so a new
// estimator takes a tag no other uses. The values are ASCII words (their names in hexadecimal);
// changing one changes every result drawn from that stream.
#include <cstdint>

namespace rad::stream_tag {

// The solve.
inline constexpr uint64_t kEmitterFirstShot = 0x656d6974746572ull;  // "emitter": seed ^ tag
inline constexpr uint64_t kLightAreaMean = 0x617265616d65616eull;   // "areamean": seed ^ tag
inline constexpr uint64_t kLightShot = 0x6c69676874ull;             // "light": seed ^ tag
inline constexpr uint64_t kHierarchicalLinks = 0x48696572ull;       // "Hier": a receiver's rays

// The renders.
inline constexpr uint64_t kPixel = 0x52454e44ull;                // "REND": a pixel's first pass
inline constexpr uint64_t kAdaptivePass = 0x41444150ull;         // "ADAP": its adaptive second pass
inline constexpr uint64_t kSobolPixel = 0x534f424f4cull;         // "SOBOL": a pixel's scramble
inline constexpr uint64_t kElementMean = 0x4d45414eull;          // "MEAN": an element's mean light
inline constexpr uint64_t kLightMean = 0x4c494748ull;            // "LIGH": its lamps', sun's, sky's
inline constexpr uint64_t kSplitDirect = 0x6469726563740000ull;  // "direct": the split's emitters

// Lightmaps and probes (the page is added to a texel's tag: each page its own streams).
inline constexpr uint64_t kLightmapTexel = 0x6c6d6170ull;     // "lmap" + page
inline constexpr uint64_t kDirectionalTexel = 0x4c315348ull;  // "L1SH" + page
inline constexpr uint64_t kProbe = 0x50524f42ull;             // "PROB": a probe's rays

}  // namespace rad::stream_tag
