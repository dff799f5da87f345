#pragma once

#include <string>

#include "radiosity/scene/scene.h"
#include "radiosity/scene/two_sided.h"

namespace rad {

// Loads a scene file of any format radiosity reads (OBJ + MTL through loadObjScene, glTF 2.0 .gltf
// and .glb through loadGltfScene). The
// format is recognised by the file's extension AND its first bytes: binary glTF (magic "glTF"),
// a JSON object (glTF 2.0 when the extension is .gltf), PLY ("ply"), else OBJ by the extension
// .obj. Throws InputError naming the file:
//   - "cannot open scene file" when it cannot be read;
//   - "unsupported scene format (<what was recognised>): radiosity reads <formats>" for a format
//     radiosity does not read, an unknown extension, or content that contradicts the extension
//     (an .obj that holds binary glTF or PLY);
//   - whatever the format's loader throws for bad content (a texture it cannot read included,
//     unless `unreadable` says to use the material's colour: scene.h).
Scene loadScene(const std::string& path,
                UnreadableTextures unreadable = UnreadableTextures::Refuse);

// The scene with its lights (findSceneLights, lights.h) and its two-sided surfaces (the file's
// own, e.g. glTF doubleSided, plus `twoSided`), each given its back side (addBackSides): the one
// loader of every command that solves or renders.
// The commands pass SolveOptions::unreadableTextures (--strict); the default here is strict.
Scene loadScene(const std::string& path, const LightInput& lights,
                const TwoSidedInput& twoSided = {},
                UnreadableTextures unreadable = UnreadableTextures::Refuse);

// Whether the scene file carries lights of its own (glTF's KHR_lights_punctual), which
// loadScene(path, lights) puts before the lights file's; false for formats without lights.
bool sceneHasOwnLights(const std::string& path);

// The formats loadScene reads, for messages and --help: "OBJ (.obj), binary glTF (.glb), ...".
std::string readableSceneFormats();

}  // namespace rad
