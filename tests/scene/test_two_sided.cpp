// Two-sided surfaces in the scene: --two-sided / --two-sided-materials mark materials, and each
// two-sided polygon gets a reversed copy with vertices of its own (its back side).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/scene/two_sided.h"

namespace rad {
namespace {

// Two quads (materials "wall" and "floor") sharing an edge, counter-clockwise from the front.
Scene twoQuads() {
  Scene scene;
  scene.sourcePath = "rooms.obj";
  scene.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}};
  for (const char* name : {"wall", "floor"}) {
    Material m;
    m.name = name;
    m.diffuse = Rgb::all(0.5);
    scene.materials.push_back(m);
  }
  ScenePolygon wall;
  wall.vertices = {0, 1, 2, 3};
  wall.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  wall.material = 0;
  wall.sourceLine = 7;
  ScenePolygon floor;
  floor.vertices = {0, 4, 5, 1};
  floor.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  floor.material = 1;
  scene.polygons = {wall, floor};
  return scene;
}

Eigen::Vector3d polygonNormal(const Scene& scene, const ScenePolygon& p) {
  const Eigen::Vector3d a = scene.positions[p.vertices[0]], b = scene.positions[p.vertices[1]],
                        c = scene.positions[p.vertices[2]];
  return (b - a).cross(c - a).normalized();
}

TEST(TwoSided, NamedMaterialsOnly) {
  Scene scene = twoQuads();
  applyTwoSidedInput(scene, {false, {"wall"}});
  EXPECT_TRUE(scene.materials[0].twoSided);
  EXPECT_FALSE(scene.materials[1].twoSided);
}

TEST(TwoSided, AllMaterials) {
  Scene scene = twoQuads();
  applyTwoSidedInput(scene, {true, {}});
  EXPECT_TRUE(scene.materials[0].twoSided);
  EXPECT_TRUE(scene.materials[1].twoSided);
}

TEST(TwoSided, AllLeavesEmittersOneSidedUnlessNamed) {
  Scene scene = twoQuads();
  scene.materials[0].emission = Rgb::all(1);
  applyTwoSidedInput(scene, {true, {}});
  EXPECT_FALSE(scene.materials[0].twoSided);
  EXPECT_TRUE(scene.materials[1].twoSided);
  applyTwoSidedInput(scene, {false, {"wall"}});
  EXPECT_TRUE(scene.materials[0].twoSided);
}

TEST(TwoSided, UnknownMaterialIsAnErrorNamingItTheOptionAndTheScene) {
  Scene scene = twoQuads();
  try {
    applyTwoSidedInput(scene, {false, {"wall", "wallpaper"}});
    FAIL() << "no error for an unknown material";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("rooms.obj"), std::string::npos) << message;
    EXPECT_NE(message.find("--two-sided-materials"), std::string::npos) << message;
    EXPECT_NE(message.find("'wallpaper'"), std::string::npos) << message;
    EXPECT_NE(message.find("wall, floor"), std::string::npos) << message;  // what there is
  }
}

TEST(TwoSided, BackSideIsAReversedCopyWithItsOwnVertices) {
  Scene scene = twoQuads();
  applyTwoSidedInput(scene, {false, {"wall"}});
  const std::size_t positions = scene.positions.size();
  EXPECT_EQ(addBackSides(scene), 1);
  ASSERT_EQ(scene.polygons.size(), 3u);
  EXPECT_EQ(scene.backSideCount(), 1);
  const ScenePolygon& front = scene.polygons[0];
  const ScenePolygon& back = scene.polygons[2];
  EXPECT_EQ(back.backSideOf, 0);
  EXPECT_EQ(front.backSideOf, -1);
  EXPECT_EQ(back.material, front.material);
  EXPECT_EQ(back.sourceLine, front.sourceLine);  // errors about it name the file's own face
  ASSERT_EQ(back.vertices.size(), 4u);
  EXPECT_EQ(scene.positions.size(), positions + 4);
  for (std::size_t k = 0; k < 4; ++k) {
    // Corner k of the back is corner 3 - k of the front: same place, same texture coordinate.
    EXPECT_GE(back.vertices[k], static_cast<int>(positions));  // a vertex of its own
    EXPECT_EQ(scene.positions[back.vertices[k]], scene.positions[front.vertices[3 - k]]);
    EXPECT_EQ(back.uvs[k], front.uvs[3 - k]);
  }
  EXPECT_NEAR(polygonNormal(scene, back).dot(polygonNormal(scene, front)), -1.0, 1e-12);
}

TEST(TwoSided, AddingBackSidesTwiceAddsNoMore) {
  Scene scene = twoQuads();
  applyTwoSidedInput(scene, {true, {}});
  EXPECT_EQ(addBackSides(scene), 2);
  EXPECT_EQ(addBackSides(scene), 0);
  EXPECT_EQ(scene.polygons.size(), 4u);
}

TEST(TwoSided, GlassGetsNoBackSide) {
  Scene scene = twoQuads();
  scene.materials[0].kind = SurfaceKind::Dielectric;  // its back is its inside
  applyTwoSidedInput(scene, {true, {}});
  EXPECT_EQ(addBackSides(scene), 1);
  EXPECT_EQ(scene.polygons.back().backSideOf, 1);  // the floor's
}

}  // namespace
}  // namespace rad
