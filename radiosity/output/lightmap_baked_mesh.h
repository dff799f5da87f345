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
// where charts meet, so every vertex has one lightmap UV, and where the scene's texture UVs split.
struct BakedMesh {
  std::vector<Eigen::Vector3d> positions, normals;
  std::vector<Eigen::Vector2d>
      uvs;  // lightmap UV, origin top-left (glTF); empty without a lightmap
  // The scene's texture UVs (what its base-colour textures are mapped with), origin top-left as
  // glTF's; empty when the scene has none.
  std::vector<Eigen::Vector2d> textureUvs;
  std::vector<Rgb> radiance;      // linear outgoing radiance per vertex, W·m⁻²·sr⁻¹
  std::vector<int> sourceVertex;  // per vertex, the VertexInterpolation vertex it was made from
  std::vector<std::array<int, 3>> triangles;  // per element, counter-clockwise from the front
  std::vector<int> materials;                 // per triangle
  std::vector<int> pages;                     // per triangle, its lightmap page (0 without)
  std::vector<std::string> materialNames;
};

// `layout` may be null (vertex colours only). `vertexRadiance` has one value per output vertex
// of `interpolation`; `materialNames` one name per material index used by the mesh. The scene's
// texture UVs come along when the mesh has them (PatchMesh::hasUvs).
BakedMesh makeBakedMesh(const PatchMesh& mesh, const VertexInterpolation& interpolation,
                        const std::vector<Rgb>& vertexRadiance, const LightmapLayout* layout,
                        const std::vector<std::string>& materialNames);

}  // namespace rad
