#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radiosity/core/image.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// OpenEXR with 32-bit float R, G, B channels: linear radiance kept exactly (an emitter's Ke
// reads back bit for bit). Written under a temporary name and renamed when complete.
void writeExr(const std::string& path, const ImageRgb& image);
// Throws InputError naming the file when it is missing or not a readable RGB EXR.
ImageRgb readExr(const std::string& path);

// 8-bit sRGB PNG through `toneMap` (see tone_map.h for the operator). Atomic like writeExr.
void writePng(const std::string& path, const ImageRgb& radiance, const ToneMap& toneMap);
// The same PNG in memory (for embedding, e.g. in a .glb).
std::vector<std::uint8_t> encodePng(const ImageRgb& radiance, const ToneMap& toneMap);

}  // namespace rad
