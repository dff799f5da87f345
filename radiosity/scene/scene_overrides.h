#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/scene/material.h"

namespace rad {

// What `radiosity relight DIR --override FILE` changes in one material: each value set replaces
// the scene's, each one unset keeps it.
struct MaterialOverride {
  std::optional<Rgb> diffuse;   // Kd: replaces the material's factor (textures still multiply it),
                                // each channel in [0, 1]
  std::optional<Rgb> emission;  // Ke: emitted radiance W·m⁻²·sr⁻¹, >= 0, finite
};

// Sets what `change` sets in `material` (relight, and a relit solution's scene when reused).
void applyMaterialOverride(Material& material, const MaterialOverride& change);

// A relight override file as read: the materials it changes and every light's scale.
struct SceneOverrides {
  std::map<int, MaterialOverride> materials;  // by material index
  std::vector<Rgb> lightScale;                // one per light, Rgb::all(1) where not overridden
};

// Reads a relight override file:
//   {"materials": {"NAME": {"diffuse": [r, g, b], "emission": [r, g, b], "comment": "..."}, ...},
//    "lights": {"KEY": {"scale": k | [r, g, b], "comment": "..."}, ...},
//    "comment": "..."}
// Both top-level members are optional. A material is named as in the scene: materialNames[i] is
// material i's name (a name several materials share overrides each of them). A light KEY is either
// a light's index (decimal digits, no leading zero, < lightGroups.size()) or a light group's name:
// lightGroups[i] is light i's group name ("" for none), and a group key scales every light of that
// group. Digits name the index first: a group named "1" is reached by that key only when the scene
// has at most one light. A light named both by its index and by its group takes the index's scale
// (it is more specific). scale: one number (every channel) or an RGB triple, each finite and >= 0.
// Any other content (an unknown key or name, a value of the wrong type or out of range, a material
// entry that changes nothing, a light entry without "scale") is an InputError naming the file, the
// line and the JSON pointer of the bad value, as a missing file or malformed JSON is.
SceneOverrides loadSceneOverrides(const std::string& path,
                                  const std::vector<std::string>& materialNames,
                                  const std::vector<std::string>& lightGroups);

}  // namespace rad
