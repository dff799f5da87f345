#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

#include "radiosity/output/lightmap_baked_mesh.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// Writes the baked scene as binary glTF 2.0 (.glb): positions, normals, one primitive per scene
// material, and per vertex
//   COLOR_0     float RGB, the tone-mapped colour in linear space, clamp(exposure × L, 0, 1);
//   _RADIANCE   float RGB, the linear outgoing radiance L itself (W·m⁻²·sr⁻¹, unclamped);
//   TEXCOORD_0 and TEXCOORD_1, the lightmap UVs (one accessor), when `lightmapPng` is given.
// With a lightmap, every material shows it as emissiveTexture (texCoord 1, emissiveFactor 1) over
// a black, rough, non-metallic base: core glTF that Blender, three.js, Babylon and game engines
// show as the baked colours whatever lights a viewer adds, and COLOR_0, multiplying a black base,
// adds nothing. Without a lightmap the materials are KHR_materials_unlit with a white base, so
// COLOR_0 is what shows. The exposure and what the lightmap holds (`content`) are in
// asset.extras.radiosity. Open `out` in binary mode. Throws RuntimeFailure if tinygltf fails to
// serialise.
void writeBakedGlb(std::ostream& out, const BakedMesh& mesh,
                   const std::vector<std::uint8_t>* lightmapPng, const ToneMap& toneMap,
                   LightmapContent content = LightmapContent::Radiance);

}  // namespace rad
