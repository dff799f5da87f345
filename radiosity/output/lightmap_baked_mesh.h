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

// How far the back copies of two-sided surfaces go out behind their front sides, as a share of
// the mesh's bounds diagonal (1.5 mm in a 15 m scene): far beyond float rounding, far below a
// texel.
inline constexpr double kBackSideLift = 1e-4;

// `layout` may be null (vertex colours only). `vertexRadiance` has one value per output vertex
// of `interpolation`; `materialNames` one name per material index used by the mesh. The scene's
// texture UVs come along when the mesh has them (PatchMesh::hasUvs).
// `backSidePatches` (empty, or one per patch): the patches that are the back copies of two-sided
// surfaces (ScenePolygon::backSideOf). Their vertices go out moved along their own normal, away
// from the front side, by kBackSideLift of the bounds diagonal: a renderer that does not cull
// back faces (Cycles, Eevee, most glTF viewers) would otherwise show whichever of two coincident
// copies a ray meets first, and so the wrong side's lightmap over half the surface. Moved apart,
// a ray from either side meets that side's own copy first.
BakedMesh makeBakedMesh(const PatchMesh& mesh, const VertexInterpolation& interpolation,
                        const std::vector<Rgb>& vertexRadiance, const LightmapLayout* layout,
                        const std::vector<std::string>& materialNames,
                        const std::vector<char>& backSidePatches = {});

}  // namespace rad
