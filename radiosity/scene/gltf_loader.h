#pragma once

#include <optional>
#include <string>

#include "radiosity/scene/camera.h"
#include "radiosity/scene/scene.h"

namespace rad {

// Photometric to radiometric units for KHR_lights_punctual: glTF gives point and spot intensity
// in candela and directional illuminance in lux; radiosity's lights are in W·sr⁻¹ and W·m⁻². The
// rule is 683 lm/W (the luminous efficacy of 555 nm light, the SI definition of the candela),
// the same constant Blender's glTF exporter and importer use: cd / 683 = W·sr⁻¹, lx / 683 = W·m⁻².
constexpr double kLumensPerWatt = 683.0;

// Loads a glTF 2.0 scene (.gltf with its external or data-URI buffers and images, or .glb)
// through tinygltf: the default scene's nodes with their transforms, every TRIANGLES (and strip,
// fan) primitive as triangles, materials (metallic-roughness as reflectance, emissive ×
// KHR_materials_emissive_strength as radiance in W·m⁻²·sr⁻¹, mirrors, transmission as
// dielectrics), TEXCOORD_0/1 with v flipped to point up, and KHR_lights_punctual lights (see
// docs/formats.md). Throws InputError naming the file and the JSON pointer of what is wrong
// (missing buffer or image file, ranges, indices, non-finite positions, unsupported required
// extensions; an image it cannot decode, unless `unreadable` is UseMaterialColour: then a
// warning and a fallback, scene.h).
Scene loadGltfScene(const std::string& path,
                    UnreadableTextures unreadable = UnreadableTextures::Refuse);

// Whether a node of the default scene carries a KHR_lights_punctual light (without reading the
// geometry or decoding images): for the checks that run before a scene is loaded.
bool gltfSceneHasLights(const std::string& path);

// The camera of the default scene's first node that has a perspective camera (its world
// position, -z view and +y up, yfov; the aspect ratio sets the width at the default height), or
// nullopt when there is none. Throws as loadGltfScene for a file it cannot read.
std::optional<Camera> loadGltfCamera(const std::string& path);

}  // namespace rad
