#include "radiosity/output/lightmap_baked_mesh.h"

#include <map>
#include <tuple>
#include <utility>

#include "radiosity/core/check.h"

namespace rad {

BakedMesh makeBakedMesh(const PatchMesh& mesh, const VertexInterpolation& interpolation,
                        const std::vector<Rgb>& vertexRadiance, const LightmapLayout* layout,
                        const std::vector<std::string>& materialNames,
                        const std::vector<char>& backSidePatches) {
  RAD_CHECK_EQ(vertexRadiance.size(), interpolation.vertexCount());  // one per output vertex
  RAD_CHECK(backSidePatches.empty() ||
            backSidePatches.size() == static_cast<size_t>(mesh.patchCount()));
  const double lift = kBackSideLift * mesh.boundsDiagonal();
  BakedMesh out;
  out.materialNames = materialNames;
  // (interpolated vertex, chart, lightmap UV, texture UV) → output vertex. Within a generated
  // chart a vertex has one UV; a scene's UV island may still cut a vertex (a seam ending inside
  // the island), and texture seams cut vertices too.
  std::map<std::tuple<int, int, double, double, double, double>, int> index;
  // Texture UVs go out where any element has them (zero on those without: their materials have
  // no texture to look up).
  bool anyTextureUvs = false;
  for (int e = 0; e < mesh.elementCount() && !anyTextureUvs; ++e) anyTextureUvs = mesh.hasUvs(e);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const int chart = layout ? layout->chartOfElement[e] : 0;
    // Zero where the element has none: Eigen's vectors are not zeroed by `{}`, and these are keys.
    const Eigen::Vector2d none = Eigen::Vector2d::Zero();
    const std::array<Eigen::Vector2d, 3> textureUvs =
        mesh.hasUvs(e) ? mesh.cornerUvs(e) : std::array<Eigen::Vector2d, 3>{none, none, none};
    const bool backSide = !backSidePatches.empty() && backSidePatches[mesh.patch(e)];
    std::array<int, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const int v = interpolation.triangle(e)[k];
      const Eigen::Vector2d uv = layout ? layout->uv(e, k) : Eigen::Vector2d::Zero();
      // The scene's UVs have v up (OBJ); glTF's origin is the top-left corner.
      const Eigen::Vector2d textureUv(textureUvs[k].x(), 1.0 - textureUvs[k].y());
      auto [it, inserted] =
          index.emplace(std::make_tuple(v, chart, uv.x(), uv.y(), textureUv.x(), textureUv.y()),
                        static_cast<int>(out.positions.size()));
      if (inserted) {
        // A back copy's vertices are its own (VertexInterpolation splits them off the front's by
        // their opposite normals), so moving them moves no front triangle.
        out.positions.push_back(
            backSide ? Eigen::Vector3d(interpolation.position(v) + lift * interpolation.normal(v))
                     : interpolation.position(v));
        out.normals.push_back(interpolation.normal(v));
        out.radiance.push_back(vertexRadiance[v]);
        out.sourceVertex.push_back(v);
        if (layout) out.uvs.push_back(uv);
        if (anyTextureUvs) out.textureUvs.push_back(textureUv);
      }
      tri[k] = it->second;
    }
    out.triangles.push_back(tri);
    out.pages.push_back(layout ? layout->page(e) : 0);
    const int m = mesh.material(e);
    RAD_CHECK_MSG(m >= 0 && m < static_cast<int>(materialNames.size()),
                  "makeBakedMesh: material index without a name");
    out.materials.push_back(m);
  }
  return out;
}

}  // namespace rad
