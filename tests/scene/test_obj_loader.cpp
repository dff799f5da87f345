// Loading the scenes under data/: counts, materials, orientation, and every bad-input fixture.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

const std::string kData = RADIOSITY_DATA_DIR;

// Newell's vector area: its direction is the normal given by the winding (right-hand rule).
Eigen::Vector3d vectorArea(const Scene& scene, const ScenePolygon& polygon) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const std::size_t n = polygon.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    sum +=
        scene.positions[polygon.vertices[i]].cross(scene.positions[polygon.vertices[(i + 1) % n]]);
  }
  return 0.5 * sum;
}

Eigen::Vector3d centroid(const Scene& scene, const ScenePolygon& polygon) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int v : polygon.vertices) sum += scene.positions[v];
  return sum / static_cast<double>(polygon.vertices.size());
}

const std::string& materialOf(const Scene& scene, const ScenePolygon& polygon) {
  return scene.materials[polygon.material].name;
}

// Expects the load (or requireEmitter) to fail with "<file>:<line>: ..." containing `phrase`.
void expectInputError(const std::string& objPath, const std::string& fileInMessage, int line,
                      const std::string& phrase, bool requireLight = false) {
  try {
    const Scene scene = loadObjScene(objPath);
    if (requireLight) requireEmitter(scene);
    FAIL() << objPath << " loaded without an error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string location =
        line > 0 ? fileInMessage + ":" + std::to_string(line) + ": " : fileInMessage + ": ";
    EXPECT_NE(what.find(location), std::string::npos) << what;
    EXPECT_NE(what.find(phrase), std::string::npos) << what;
    EXPECT_EQ(e.line(), line) << what;
  }
}

TEST(ObjLoader, CornellBoxCountsAndMaterials) {
  const Scene scene = loadObjScene(kData + "/cornell_box/cornell_box.obj");
  EXPECT_EQ(scene.positions.size(), 40u);
  // floor, ceiling, light, back, right, left (2 triangles), two blocks of 5 faces
  ASSERT_EQ(scene.polygons.size(), 17u);
  ASSERT_EQ(scene.materials.size(), 4u);
  EXPECT_EQ(scene.emitterCount(), 1);
  EXPECT_FALSE(scene.hasSpecular());
  EXPECT_EQ(scene.skippedDegenerateFaces, 0);
  EXPECT_FALSE(scene.usedDefaultMaterial);

  const std::vector<std::string> names = {"white", "red", "green", "light"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(scene.materials[i].name, names[i]);
    EXPECT_EQ(scene.materials[i].kind, SurfaceKind::Diffuse);
    EXPECT_NE(scene.materials[i].sourceFile.find("cornell_box.mtl"), std::string::npos);
  }
  EXPECT_EQ(scene.materials[0].sourceLine, 4);
  EXPECT_EQ(scene.materials[3].sourceLine, 19);
  EXPECT_NEAR(scene.materials[0].diffuse.r, 0.725, 1e-12);
  EXPECT_NEAR(scene.materials[1].diffuse.g, 0.065, 1e-12);
  EXPECT_NEAR(scene.materials[2].diffuse.b, 0.091, 1e-12);
  EXPECT_NEAR(scene.materials[3].emission.r, 17, 1e-12);
  EXPECT_NEAR(scene.materials[3].emission.g, 12, 1e-12);
  EXPECT_NEAR(scene.materials[3].emission.b, 4, 1e-12);
  EXPECT_TRUE(scene.materials[0].emission.isZero());

  EXPECT_EQ(materialOf(scene, scene.polygons[2]), "light");
  EXPECT_EQ(scene.polygons[2].sourceLine, 29);
  EXPECT_EQ(materialOf(scene, scene.polygons[4]), "green");
  EXPECT_EQ(materialOf(scene, scene.polygons[5]), "red");
  EXPECT_EQ(materialOf(scene, scene.polygons[6]), "red");
}

TEST(ObjLoader, CornellBoxLightFacesDownBelowTheCeiling) {
  const Scene scene = loadObjScene(kData + "/cornell_box/cornell_box.obj");
  const ScenePolygon& light = scene.polygons[2];
  ASSERT_TRUE(scene.materials[light.material].isEmitter());
  const Eigen::Vector3d area = vectorArea(scene, light);
  EXPECT_NEAR(area.norm(), 0.130 * 0.105, 1e-12);
  EXPECT_NEAR(area.normalized().y(), -1.0, 1e-12);
  for (int v : light.vertices) EXPECT_NEAR(scene.positions[v].y(), 0.5487, 1e-12);
}

TEST(ObjLoader, CornellBoxWallsFaceInwardAndBlocksOutward) {
  const Scene scene = loadObjScene(kData + "/cornell_box/cornell_box.obj");
  const Eigen::Vector3d boxCentre(0.278, 0.2744, 0.2796);
  for (std::size_t i = 0; i < 7; ++i) {  // walls, floor, ceiling, light
    const ScenePolygon& p = scene.polygons[i];
    const Eigen::Vector3d n = vectorArea(scene, p).normalized();
    EXPECT_GT(n.dot((boxCentre - centroid(scene, p)).normalized()), 0.5) << "line " << p.sourceLine;
  }
  // Blocks are convex: every vertex of a block lies behind each of its faces' planes.
  for (std::size_t first : {std::size_t{7}, std::size_t{12}}) {
    std::vector<int> blockVertices;
    for (std::size_t i = first; i < first + 5; ++i) {
      for (int v : scene.polygons[i].vertices) blockVertices.push_back(v);
    }
    for (std::size_t i = first; i < first + 5; ++i) {
      const ScenePolygon& p = scene.polygons[i];
      const Eigen::Vector3d n = vectorArea(scene, p).normalized();
      const Eigen::Vector3d c = centroid(scene, p);
      for (int v : blockVertices) {
        EXPECT_LE(n.dot(scene.positions[v] - c), 1e-9) << "line " << p.sourceLine;
      }
      EXPECT_GE(n.y(), -1e-12) << "a block has no bottom face; line " << p.sourceLine;
    }
  }
}

TEST(ObjLoader, FurnaceBoxIsAClosedInwardCube) {
  const Scene scene = loadObjScene(kData + "/tests/furnace_box.obj");
  ASSERT_EQ(scene.polygons.size(), 6u);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "furnace");
  EXPECT_EQ(scene.emitterCount(), 6);
  EXPECT_DOUBLE_EQ(scene.materials[0].diffuse.g, 0.5);
  EXPECT_DOUBLE_EQ(scene.materials[0].emission.b, 1.0);
  Eigen::Vector3d closure = Eigen::Vector3d::Zero();
  for (const ScenePolygon& p : scene.polygons) {
    const Eigen::Vector3d area = vectorArea(scene, p);
    EXPECT_NEAR(area.norm(), 1.0, 1e-15);
    const Eigen::Vector3d toCentre = Eigen::Vector3d::Constant(0.5) - centroid(scene, p);
    EXPECT_NEAR(area.dot(toCentre), 0.5, 1e-15) << "line " << p.sourceLine;
    closure += area;
  }
  EXPECT_LT(closure.norm(), 1e-15);  // a closed surface has zero total vector area
}

TEST(ObjLoader, SquarePairsFaceEachOther) {
  const Scene parallel = loadObjScene(kData + "/tests/parallel_squares.obj");
  ASSERT_EQ(parallel.polygons.size(), 2u);
  EXPECT_EQ(parallel.emitterCount(), 1);
  EXPECT_EQ(materialOf(parallel, parallel.polygons[0]), "source");
  EXPECT_EQ(materialOf(parallel, parallel.polygons[1]), "receiver");
  EXPECT_TRUE(vectorArea(parallel, parallel.polygons[0]).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(vectorArea(parallel, parallel.polygons[1]).isApprox(Eigen::Vector3d(0, 0, -1)));

  const Scene perpendicular = loadObjScene(kData + "/tests/perpendicular_squares.obj");
  ASSERT_EQ(perpendicular.polygons.size(), 2u);
  EXPECT_EQ(perpendicular.positions.size(), 6u);  // the shared edge shares its vertices
  EXPECT_TRUE(
      vectorArea(perpendicular, perpendicular.polygons[0]).isApprox(Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(
      vectorArea(perpendicular, perpendicular.polygons[1]).isApprox(Eigen::Vector3d(0, 0, 1)));
}

TEST(ObjLoader, DegenerateFacesAreSkippedAndCounted) {
  const Scene scene = loadObjScene(kData + "/tests/degenerate_faces.obj");
  EXPECT_EQ(scene.skippedDegenerateFaces, 2);
  ASSERT_EQ(scene.polygons.size(), 2u);
  EXPECT_EQ(scene.polygons[0].sourceLine, 14);
  EXPECT_EQ(scene.polygons[1].sourceLine, 16);
}

TEST(ObjLoader, FacesWithoutUsemtlGetTheDefaultMaterial) {
  const Scene scene = loadObjScene(kData + "/tests/no_usemtl.obj");
  EXPECT_TRUE(scene.usedDefaultMaterial);
  ASSERT_EQ(scene.materials.size(), 3u);  // source, receiver, then the appended default
  ASSERT_EQ(scene.polygons.size(), 2u);
  const Material& fallback = scene.materials[scene.polygons[0].material];
  EXPECT_EQ(scene.polygons[0].material, 2);
  EXPECT_EQ(fallback.name, "default");
  EXPECT_DOUBLE_EQ(fallback.diffuse.r, 0.5);
  EXPECT_FALSE(fallback.isEmitter());
  EXPECT_EQ(materialOf(scene, scene.polygons[1]), "source");
}

TEST(ObjLoader, MissingObjFile) {
  const std::string path = kData + "/tests/does_not_exist.obj";
  expectInputError(path, path, 0, "cannot open");
}

const std::string kBad = kData + "/tests/bad/";

TEST(ObjLoaderBadInput, NanVertex) {
  expectInputError(kBad + "nan_vertex.obj", "nan_vertex.obj", 5, "non-finite number 'nan'");
}

TEST(ObjLoaderBadInput, MalformedNumber) {
  expectInputError(kBad + "malformed_number.obj", "malformed_number.obj", 5,
                   "malformed number 'abc'");
}

TEST(ObjLoaderBadInput, MissingMaterial) {
  expectInputError(kBad + "missing_material.obj", "missing_material.obj", 13,
                   "missing material 'unknown_material'");
}

TEST(ObjLoaderBadInput, MissingMtllib) {
  expectInputError(kBad + "missing_mtllib.obj", "missing_mtllib.obj", 2,
                   "cannot open material library 'does_not_exist.mtl'");
}

TEST(ObjLoaderBadInput, ReflectanceAboveOne) {
  expectInputError(kBad + "reflectance_above_one.obj", "reflectance_above_one.mtl", 8,
                   "reflectance must be in [0, 1]");
}

TEST(ObjLoaderBadInput, NegativeEmission) {
  expectInputError(kBad + "negative_emission.obj", "negative_emission.mtl", 4,
                   "emission must be non-negative");
}

TEST(ObjLoaderBadInput, BadIndex) {
  expectInputError(kBad + "bad_index.obj", "bad_index.obj", 14, "vertex index 9 is out of range");
}

TEST(ObjLoaderBadInput, ShortFace) {
  expectInputError(kBad + "short_face.obj", "short_face.obj", 14, "a face needs at least 3");
}

TEST(ObjLoaderBadInput, NoEmitterLoadsButIsRejectedByRequireEmitter) {
  const std::string path = kBad + "no_emitter.obj";
  const Scene scene = loadObjScene(path);
  EXPECT_EQ(scene.emitterCount(), 0);
  expectInputError(path, path, 0, "no emitter", /*requireLight=*/true);
}

}  // namespace
}  // namespace rad
