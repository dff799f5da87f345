#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radiosity/core/atomic_file.h"
#include "radiosity/core/image.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// OpenEXR with 32-bit float R, G, B channels: linear radiance kept exactly (an emitter's Ke
// reads back bit for bit). Written under a temporary name and renamed when complete.
void writeExr(const std::string& path, const ImageRgb& image);
// Throws InputError naming the file when it is missing or not a readable RGB EXR.
ImageRgb readExr(const std::string& path);

// One more 32-bit float channel of an EXR beside R, G, B: its name (no '.', so the file stays a
// single-layer RGB image to readers that know only R, G, B, Blender's included) and one value per
// pixel, row-major like ImageRgb::pixels.
struct ExrChannel {
  std::string name;
  std::vector<float> values;
};
// writeExr with extra channels (e.g. the lightmap's "error"); readExr reads its R, G, B alike.
// RAD_CHECK (CheckFailure) when a channel's size is not the image's or its name is R, G, B.
void writeExr(const std::string& path, const ImageRgb& image, const std::vector<ExrChannel>& extra);
// The same under `file`'s temporary name, left for the caller to commit with the other files of
// its set (so one written early, beside others, takes its name only when all are complete).
void writeExr(const AtomicPath& file, const ImageRgb& image, const std::vector<ExrChannel>& extra);
// The channel `name` of an EXR file, row-major over its data window. Throws InputError naming the
// file when it is missing, unreadable or has no such channel.
std::vector<float> readExrChannel(const std::string& path, const std::string& name);

// 8-bit sRGB PNG through `toneMap` (see tone_map.h for the operator). Atomic like writeExr.
void writePng(const std::string& path, const ImageRgb& radiance, const ToneMap& toneMap);
// The same PNG in memory (for embedding, e.g. in a .glb).
std::vector<std::uint8_t> encodePng(const ImageRgb& radiance, const ToneMap& toneMap);

}  // namespace rad
