#pragma once

#include <string>

#include "radiosity/scene/scene.h"

namespace rad {

// Loads an OBJ file and the MTL libraries it names (through tinyobjloader), then validates it.
// Throws InputError with "file:line: message" for: a missing/unreadable file, a missing MTL
// library, `usemtl` of an unknown material, malformed or non-finite numbers, vertex indices out of
// range, reflectance outside [0, 1), negative emission. Zero-area faces are skipped and counted.
// A scene without any emitter is NOT an error here (the solver decides); see requireEmitter()
// (scene.h). A texture file it cannot read is an InputError at its MTL line, or with
// UseMaterialColour a warning and a fallback (scene.h). Callers outside scene/ load through
// loadScene (scene_loader.h), which picks the format.
Scene loadObjScene(const std::string& objPath,
                   UnreadableTextures unreadable = UnreadableTextures::Refuse);

}  // namespace rad
