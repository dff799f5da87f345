#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/patch_mesh.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/rgb.h"

namespace rad {

// The mesh the baked exports (glTF, OBJ) write: one triangle per element, vertices split where
// the vertex colours split (material, crease; see VertexInterpolation) and, with a lightmap,
// where charts meet, so every vertex has one lightmap UV.
struct BakedMesh {
  std::vector<Eigen::Vector3d> positions, normals;
  std::vector<Eigen::Vector2d>
      uvs;                    // lightmap UV, origin top-left (glTF); empty without a lightmap
  std::vector<Rgb> radiance;  // linear outgoing radiance per vertex, W·m⁻²·sr⁻¹
  std::vector<std::array<int, 3>> triangles;  // per element, counter-clockwise from the front
  std::vector<int> materials;                 // per triangle
  std::vector<std::string> materialNames;
};

// `layout` may be null (vertex colours only). `vertexRadiance` has one value per output vertex
// of `interpolation`; `materialNames` one name per material index used by the mesh.
BakedMesh makeBakedMesh(const PatchMesh& mesh, const VertexInterpolation& interpolation,
                        const std::vector<Rgb>& vertexRadiance, const LightmapLayout* layout,
                        const std::vector<std::string>& materialNames);

}  // namespace rad
