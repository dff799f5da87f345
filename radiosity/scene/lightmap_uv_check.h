#pragma once

#include "radiosity/scene/scene.h"

namespace rad {

// Checks that the scene's own texture coordinates can serve as lightmap UVs (bake
// --use-scene-uvs): every face has them, all lie in [0, 1]², every triangle a face is split into
// has non-zero area in UV, and no two triangles overlap in UV (shared edges and corners may
// touch). Throws InputError "file:line: ..." at the first face that breaks a rule, naming the
// other face of an overlap.
void checkLightmapUvs(const Scene& scene);

}  // namespace rad
