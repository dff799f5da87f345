#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radiosity/scene/lights.h"
#include "radiosity/scene/material.h"
#include "radiosity/scene/texture.h"

namespace rad {

// One input polygon (an OBJ face). It becomes one patch of the PatchMesh.
struct ScenePolygon {
  std::vector<int>
      vertices;        // indices into Scene::positions, counter-clockwise seen from the front
  int material = 0;    // index into Scene::materials
  int sourceLine = 0;  // line of the `f` statement in the OBJ file
  // The `vt` of each corner (u, v with v up, as OBJ writes it), or empty when some corner has none:
  // the texture coordinates (glTF's TEXCOORD_0, its v flipped to point up).
  std::vector<Eigen::Vector2d> uvs;
  std::string object;  // name of the OBJ `o`/`g` group the face belongs to ("" if none)
  // Lightmap coordinates when the scene has a set of its own (glTF's TEXCOORD_1); when empty,
  // `uvs` serve for --use-scene-uvs too.
  std::vector<Eigen::Vector2d> lightmapUvs;
  // For the back side of a two-sided surface (addBackSides, two_sided.h): the polygon it is the
  // reversed copy of; -1 for a polygon of the scene file.
  int backSideOf = -1;
};

// What loading does with a texture file it cannot read (missing, or not an image it decodes).
enum class UnreadableTextures {
  // A warning naming the file and line (or JSON pointer), the material's own colour used instead,
  // and the texture listed in Scene::textureFallbacks: Blender and game engines go on too.
  UseMaterialColour,
  Refuse,  // an InputError at that line (--strict)
};

// A validated scene: every polygon has >= 3 distinct, in-range vertices and non-zero area,
// every material has finite values with diffuse in [0, 1] and emission >= 0.
struct Scene {
  std::string sourcePath;
  std::vector<Eigen::Vector3d> positions;
  std::vector<ScenePolygon> polygons;
  std::vector<Material> materials;
  std::vector<Texture> textures;  // referenced by Material::*Texture
  std::vector<Light> lights;      // besides emissive polygons (a lights file, --sky, --sun)

  int skippedDegenerateFaces = 0;    // zero-area or repeated-vertex faces, skipped with a warning
  bool usedDefaultMaterial = false;  // some faces had no `usemtl`
  // Each texture not read ("file.mtl:5: texture: x.png: cannot open the texture file"), its
  // material's own colour used instead (UnreadableTextures::UseMaterialColour).
  std::vector<std::string> textureFallbacks;

  int emitterCount() const;     // polygons whose material emits
  bool hasSpecular() const;     // any polygon with a mirror or dielectric material
  int polygonsWithUvs() const;  // polygons whose corners all have texture coordinates
  int backSideCount() const;    // polygons that are the back side of a two-sided surface
};

// Throws InputError naming the scene file when no polygon emits and the scene has no light
// (whatever format it came from).
void requireEmitter(const Scene& scene);

}  // namespace rad
