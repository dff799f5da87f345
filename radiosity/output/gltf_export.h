#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "radiosity/output/lightmap_baked_mesh.h"
#include "radiosity/output/lightmap_content.h"
#include "radiosity/output/tone_map.h"

namespace rad {

// An image file's bytes as a glTF image holds them (PNG or JPEG, the formats core glTF allows).
struct EncodedImage {
  std::string name;
  std::string mimeType;  // "image/png" or "image/jpeg"
  std::vector<std::uint8_t> bytes;
};

// A scene material's base colour, kept in the export so an engine can relight the model:
// baseColorFactor = factor, times baseColorTexture = images[image] on TEXCOORD_0 when image ≥ 0.
struct BaseColour {
  Rgb factor = Rgb::all(1.0);
  int image = -1;
};

// One light group's layer in the baked glTF (bake --light-groups).
struct BakedLayer {
  std::string name;                                      // the group's name
  std::vector<Rgb> radiance;                             // per BakedMesh vertex, linear
  std::vector<std::vector<std::uint8_t>> lightmapPages;  // PNG per page, the whole's exposure
  std::vector<std::string> exrFiles;                     // its linear lightmap pages beside the glb
};

// What the baked glTF shows besides its geometry and vertex colours.
struct BakedLook {
  std::vector<std::vector<std::uint8_t>> lightmapPages;  // one PNG per page; none: colours only
  std::vector<BaseColour> baseColours;  // per material of the BakedMesh; empty: black base
  std::vector<EncodedImage> images;     // the base-colour images BaseColour::image indexes
  std::vector<BakedLayer> layers;       // light groups; empty without --light-groups
};

// Writes the baked scene as binary glTF 2.0 (.glb): positions, normals, one primitive per scene
// material and lightmap page, and per vertex
//   COLOR_0     float RGB, the tone-mapped colour in linear space, clamp(exposure × L, 0, 1);
//   _RADIANCE   float RGB, the linear outgoing radiance L itself (W·m⁻²·sr⁻¹, unclamped);
//   TEXCOORD_0  the scene's texture UVs when the mesh has them (the base colour's), else the
//               lightmap UVs (for viewers that read only the first set);
//   TEXCOORD_1  the lightmap UVs, when there is a lightmap.
// With a lightmap, every material shows its page of it as emissiveTexture (texCoord 1,
// emissiveFactor 1) over a rough, non-metallic base: core glTF that Blender, three.js, Babylon and
// game engines show as the baked colours, and COLOR_0 (not multiplied into the base) adds nothing.
// The base is the scene's base colour (look.baseColours, its texture on TEXCOORD_0) when given —
// viewer lights then add to the baked light, as they would on the real surface — else black.
// Without a lightmap the materials are KHR_materials_unlit with a white base, so COLOR_0 is what
// shows. The exposure is in asset.extras.radiosity. With light groups (look.layers), each layer i
// adds the vertex attribute _LIGHT_GROUP_i (its linear radiance; the layers sum to _RADIANCE) and
// its lightmap pages as textures that no material uses; asset.extras.radiosity.light_groups lists
// each layer's name, attribute, texture indices and EXR files, so an engine can mix the layers at
// run time with weights of its own. Open `out` in binary mode.
// Throws RuntimeFailure if tinygltf fails to serialise.
void writeBakedGlb(std::ostream& out, const BakedMesh& mesh, const BakedLook& look,
                   const ToneMap& toneMap, LightmapContent content = LightmapContent::Radiance);

}  // namespace rad
