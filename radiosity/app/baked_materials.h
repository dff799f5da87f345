#pragma once

#include "radiosity/output/gltf_export.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The scene's base colours as the baked glTF keeps them: per material its Kd (baseColorFactor)
// and its diffuse texture (baseColorTexture on TEXCOORD_0) when `textureUvs` says the baked mesh
// carries the scene's texture coordinates. PNG and JPEG files are embedded as they are; other
// formats (TGA, BMP, HDR) are re-encoded as 8-bit sRGB PNG from the decoded texels (alpha
// dropped). Only `lightmapPages` is left for the caller to fill.
BakedLook bakedBaseColours(const Scene& scene, bool textureUvs);

}  // namespace rad
