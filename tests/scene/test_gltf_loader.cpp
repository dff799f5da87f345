// The glTF 2.0 reader: the same Scene as the OBJ reader for the same surfaces, node transforms
// and instancing against the flattened scene, texture coordinates, the photometric conversion of
// KHR_lights_punctual against a file exported by Blender 3.4, the camera, and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/scene/gltf_loader.h"
#include "radiosity/scene/lightmap_uv_check.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "tests/support/gltf_writer.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir() {
  const fs::path dir = fs::temp_directory_path() / "radiosity_gltf_loader";
  fs::create_directories(dir);
  return dir;
}

// The message of the InputError loading `path` throws ("" when it loads).
std::string errorOf(const fs::path& path) {
  try {
    loadScene(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A transform with rotation, non-uniform scale and translation (positive determinant).
Eigen::Matrix4d someTransform() {
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(Eigen::Vector3d(10, -20, 5));
  t.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  t.scale(Eigen::Vector3d(2, 0.5, 1.5));
  return t.matrix();
}

void expectRgb(const Rgb& actual, const Rgb& expected) {
  for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ(actual[c], expected[c]) << "channel " << c;
}

Eigen::Vector3d normalOf(const Scene& scene, const ScenePolygon& p) {
  const Eigen::Vector3d& a = scene.positions[p.vertices[0]];
  return (scene.positions[p.vertices[1]] - a).cross(scene.positions[p.vertices[2]] - a);
}

// One quad (two triangles) in the z = 0 plane facing +z, with texture coordinates in both sets.
tinygltf::Model quadModel() {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.emplace_back();
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<float> uv0 = {0.25f, 0.125f, 0.75f, 0.125f, 0.75f, 0.5f, 0.25f, 0.5f};
  const std::vector<float> uv1 = {0, 0, 0.5f, 0, 0.5f, 0.25f, 0, 0.25f};
  tinygltf::Primitive p;
  p.attributes["POSITION"] = test::addAccessor(model, positions, TINYGLTF_TYPE_VEC3, 3);
  p.attributes["TEXCOORD_0"] = test::addAccessor(model, uv0, TINYGLTF_TYPE_VEC2, 2);
  p.attributes["TEXCOORD_1"] = test::addAccessor(model, uv1, TINYGLTF_TYPE_VEC2, 2);
  const std::vector<std::uint16_t> indices = {0, 1, 2, 0, 2, 3};
  tinygltf::Accessor a;
  a.bufferView = test::addBufferView(model, indices.data(), indices.size() * 2);
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  a.count = indices.size();
  a.type = TINYGLTF_TYPE_SCALAR;
  model.accessors.push_back(a);
  p.indices = static_cast<int>(model.accessors.size()) - 1;
  p.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Material grey;
  grey.pbrMetallicRoughness.baseColorFactor = {0.5, 0.25, 0.125, 1};
  grey.pbrMetallicRoughness.metallicFactor = 0;
  grey.emissiveFactor = {1, 0.5, 0.25};
  model.materials.push_back(grey);
  p.material = 0;
  tinygltf::Mesh mesh;
  mesh.primitives.push_back(p);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

std::string write(const tinygltf::Model& model, const std::string& name) {
  const std::string path = (scratchDir() / name).string();
  EXPECT_TRUE(test::writeGltf(model, path));
  return path;
}

TEST(GltfLoader, CornellBoxUnderATransformedNodeIsTheObjSceneTriangulated) {
  const Scene obj = loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj");
  const Scene reference = test::fanTriangulated(obj);
  for (const char* name : {"cornell.gltf", "cornell.glb"}) {
    const std::string path = write(test::gltfModel(obj, someTransform()), name);
    const Scene gltf = loadScene(path);
    ASSERT_EQ(gltf.polygons.size(), reference.polygons.size()) << name;
    ASSERT_EQ(gltf.materials.size(), obj.materials.size()) << name;
    ASSERT_EQ(gltf.positions.size(), reference.positions.size()) << name;
    // Positions went through float32 in local space: a few float ulps of the box's ~560 size.
    const double tolerance = 560 * 4 * 6e-8 * someTransform().norm();
    for (std::size_t i = 0; i < gltf.polygons.size(); ++i) {
      const ScenePolygon& g = gltf.polygons[i];
      const ScenePolygon& r = reference.polygons[i];
      ASSERT_EQ(g.material, r.material);
      EXPECT_EQ(g.vertices, r.vertices) << "the same vertices, shared the same way";
      for (int k = 0; k < 3; ++k)
        EXPECT_LT((gltf.positions[g.vertices[k]] - reference.positions[r.vertices[k]]).norm(),
                  tolerance)
            << name << " triangle " << i;
      EXPECT_GT(normalOf(gltf, g).dot(normalOf(reference, r)), 0) << "winding of " << i;
    }
    for (std::size_t m = 0; m < obj.materials.size(); ++m) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(gltf.materials[m].diffuse[c], obj.materials[m].diffuse[c], 1e-12);
        // Emission = colour (max 1) × KHR_materials_emissive_strength, the radiance itself.
        EXPECT_NEAR(gltf.materials[m].emission[c], obj.materials[m].emission[c],
                    1e-12 * obj.materials[m].emission.maxComponent());
      }
      EXPECT_EQ(gltf.materials[m].kind, SurfaceKind::Diffuse);
    }
    EXPECT_EQ(gltf.emitterCount(), reference.emitterCount());
  }
}

TEST(GltfLoader, InstancedRotatedScaledAndMirroredNodesEqualTheFlattenedScene) {
  tinygltf::Model model = quadModel();
  // Node 0 (the mesh) becomes a child of node 1 (TRS); node 2 instances the mesh again under a
  // mirroring matrix (x → -x), whose negative determinant must not turn the quad's front.
  model.nodes[0].translation = {1, 2, 3};
  tinygltf::Node parent;
  parent.rotation = {0, std::sin(M_PI / 4), 0, std::cos(M_PI / 4)};  // 90° about +y
  parent.scale = {2, 2, 2};
  parent.children = {0};
  model.nodes.push_back(parent);
  tinygltf::Node mirror;
  mirror.mesh = 0;
  mirror.matrix = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1};
  model.nodes.push_back(mirror);
  model.scenes[0].nodes = {1, 2};
  const Scene scene = loadScene(write(model, "instanced.glb"));
  ASSERT_EQ(scene.polygons.size(), 4u);
  // The flattened reference: world = parent · child for the first instance.
  const Eigen::Affine3d first = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()) *
                                Eigen::Scaling(2.0) * Eigen::Translation3d(1, 2, 3);
  const std::vector<Eigen::Vector3d> corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const int triangle[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_LT(
          (scene.positions[scene.polygons[t].vertices[k]] - first * corners[triangle[t][k]]).norm(),
          1e-12);
  // The quad faces +z; rotated 90° about y it faces +x, and its area scales by 2².
  for (int t = 0; t < 2; ++t)
    EXPECT_LT((normalOf(scene, scene.polygons[t]) - Eigen::Vector3d(4, 0, 0)).norm(), 1e-12);
  // The mirrored instance: corners at (5 - x, y, 0), still facing +z (its winding flipped).
  double area = 0;
  for (int t = 2; t < 4; ++t) {
    for (int v : scene.polygons[t].vertices) {
      EXPECT_NEAR(scene.positions[v].z(), 0, 1e-12);
      EXPECT_GE(scene.positions[v].x(), 4 - 1e-12);
    }
    const Eigen::Vector3d n = normalOf(scene, scene.polygons[t]);
    EXPECT_GT(n.z(), 0) << "the mirrored instance's front must stay +z";
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 1, 1e-12);
}

TEST(GltfLoader, TexcoordsFlipVToPointUpAndTheSecondSetIsTheLightmapSet) {
  const Scene scene = loadScene(write(quadModel(), "uvs.gltf"));
  ASSERT_EQ(scene.polygons.size(), 2u);
  const ScenePolygon& p = scene.polygons[0];  // corners 0, 1, 2
  ASSERT_EQ(p.uvs.size(), 3u);
  ASSERT_EQ(p.lightmapUvs.size(), 3u);
  // glTF (0.25, 0.125) from the top-left is (0.25, 0.875) from the bottom-left.
  EXPECT_EQ(p.uvs[0], Eigen::Vector2d(0.25, 0.875));
  EXPECT_EQ(p.uvs[2], Eigen::Vector2d(0.75, 0.5));
  EXPECT_EQ(p.lightmapUvs[1], Eigen::Vector2d(0.5, 1.0));
  EXPECT_EQ(p.lightmapUvs[2], Eigen::Vector2d(0.5, 0.75));
  expectRgb(scene.materials[0].diffuse, Rgb(0.5, 0.25, 0.125));
  // Emissive factor without the strength extension: strength 1, the colour is the radiance.
  expectRgb(scene.materials[0].emission, Rgb(1, 0.5, 0.25));
}

// bake --use-scene-uvs bakes into TEXCOORD_1 where the file has it: here TEXCOORD_0 tiles (it
// leaves [0, 1], which a lightmap refuses) while TEXCOORD_1 is a valid layout.
TEST(GltfLoader, SceneUvBakingPrefersTheLightmapSet) {
  tinygltf::Model model = quadModel();
  const std::vector<float> tiled = {0, 0, 2, 0, 2, 2, 0, 2};
  model.meshes[0].primitives[0].attributes["TEXCOORD_0"] =
      test::addAccessor(model, tiled, TINYGLTF_TYPE_VEC2, 2);
  const Scene scene = loadScene(write(model, "lightmap_set.glb"));
  EXPECT_NO_THROW(checkLightmapUvs(scene));
  const PatchMesh mesh = buildPatchMesh(scene);
  ASSERT_TRUE(mesh.hasLightmapUvs());
  ASSERT_TRUE(mesh.hasUvs());
  for (int e = 0; e < mesh.elementCount(); ++e) {
    for (const Eigen::Vector2d& uv : mesh.cornerLightmapUvs(e)) {
      EXPECT_LE(uv.x(), 0.5);  // TEXCOORD_1 spans [0, 0.5] × [0.75, 1] after the flip
      EXPECT_GE(uv.y(), 0.75);
    }
    // The texture set stays TEXCOORD_0 (tiled over [0, 2]², v flipped to [-1, 1]) for look-ups.
    double widest = 0;
    for (const Eigen::Vector2d& uv : mesh.cornerUvs(e)) widest = std::max(widest, uv.x());
    EXPECT_EQ(widest, 2.0);
  }
  // Without TEXCOORD_1 the tiled set is what a bake would use, and it is refused.
  model.meshes[0].primitives[0].attributes.erase("TEXCOORD_1");
  EXPECT_THROW(checkLightmapUvs(loadScene(write(model, "tiled_only.glb"))), InputError);
}

TEST(GltfLoader, StripsAndFansBecomeTrianglesFacingTheSameWay) {
  for (int mode : {TINYGLTF_MODE_TRIANGLE_STRIP, TINYGLTF_MODE_TRIANGLE_FAN}) {
    tinygltf::Model model = quadModel();
    model.meshes[0].primitives[0].indices = -1;
    model.meshes[0].primitives[0].mode = mode;
    // Strip order 0 1 3 2 and fan order 0 1 2 3 both cover the quad counter-clockwise.
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      const std::vector<float> strip = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
      model.meshes[0].primitives[0].attributes["POSITION"] =
          test::addAccessor(model, strip, TINYGLTF_TYPE_VEC3, 3);
    }
    const Scene scene = loadScene(write(model, "strip_fan.glb"));
    ASSERT_EQ(scene.polygons.size(), 2u) << mode;
    double area = 0;
    for (const ScenePolygon& p : scene.polygons) {
      const Eigen::Vector3d n = normalOf(scene, p);
      EXPECT_GT(n.z(), 0) << "mode " << mode;
      area += 0.5 * n.norm();
    }
    EXPECT_NEAR(area, 1, 1e-12) << mode;
  }
}

// data/tests/gltf/textured_quad.gltf: the quad with its buffer and a 2×2 RGBA PNG as data URIs
// (texels, top row first: red opaque, green at alpha 128, blue, white at alpha 0), alphaMode MASK.
TEST(GltfLoader, BaseColorTextureIsDecodedAsSrgbWithItsAlphaForCutouts) {
  const Scene scene = loadScene(std::string(RADIOSITY_DATA_DIR) + "/tests/gltf/textured_quad.gltf");
  ASSERT_EQ(scene.textures.size(), 1u);
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.diffuseTexture, 0);
  EXPECT_TRUE(m.alphaFromDiffuse);
  EXPECT_DOUBLE_EQ(m.alphaCutoff, 0.5);
  const Texture& t = scene.textures[0];
  ASSERT_EQ(t.width, 2);
  ASSERT_EQ(t.height, 2);
  const std::vector<float> expected = {1, 0, 0, 1, 0, 1, 0, 128 / 255.f, 0, 0, 1, 1, 1, 1, 1, 0};
  ASSERT_EQ(t.rgba.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(t.rgba[i], expected[i], 1e-6) << i;
}

TEST(GltfLoader, MaterialsMapToMirrorsDielectricsTwoSidedAndCutouts) {
  tinygltf::Model model = quadModel();
  tinygltf::Material mirror;
  mirror.pbrMetallicRoughness.baseColorFactor = {0.9, 0.8, 0.7, 1};
  mirror.pbrMetallicRoughness.metallicFactor = 1;
  mirror.pbrMetallicRoughness.roughnessFactor = 0.05;
  mirror.doubleSided = true;
  model.materials.push_back(mirror);
  tinygltf::Material glass;
  tinygltf::Value::Object transmission, ior;
  transmission["transmissionFactor"] = tinygltf::Value(1.0);
  ior["ior"] = tinygltf::Value(1.33);
  glass.extensions["KHR_materials_transmission"] = tinygltf::Value(transmission);
  glass.extensions["KHR_materials_ior"] = tinygltf::Value(ior);
  glass.alphaMode = "MASK";
  glass.alphaCutoff = 0.3;
  model.materials.push_back(glass);
  model.meshes[0].primitives.push_back(model.meshes[0].primitives[0]);
  model.meshes[0].primitives.back().material = 1;
  model.meshes[0].primitives.push_back(model.meshes[0].primitives[0]);
  model.meshes[0].primitives.back().material = 2;
  const Scene scene = loadScene(write(model, "materials.glb"));
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.materials[1].kind, SurfaceKind::Mirror);
  expectRgb(scene.materials[1].specular, Rgb(0.9, 0.8, 0.7));
  EXPECT_TRUE(scene.materials[1].twoSided);
  EXPECT_FALSE(scene.materials[0].twoSided);
  EXPECT_EQ(scene.materials[2].kind, SurfaceKind::Dielectric);
  EXPECT_DOUBLE_EQ(scene.materials[2].ior, 1.33);
  EXPECT_DOUBLE_EQ(scene.materials[2].alphaCutoff, 0.3);
}

// Blender 3.4's exporter (data/tests/gltf/make_blender_lights.py made the file) writes a point
// or spot light of P W as P/(4π)·683 cd and a sun of S W/m² as S·683 lx. Cycles gives a point
// light of P W the radiant intensity P/(4π) W/sr, and a sun of S W/m² that irradiance on a
// surface facing it: so the reader must recover exactly those.
TEST(GltfLoader, PunctualLightsExportedByBlenderHaveTheIntensitiesCyclesMeansByTheirWatts) {
  const Scene scene = loadScene(std::string(RADIOSITY_DATA_DIR) + "/tests/gltf/blender_lights.glb");
  ASSERT_EQ(scene.lights.size(), 3u);
  const Light* point = nullptr;
  const Light* spot = nullptr;
  const Light* sun = nullptr;
  for (const Light& l : scene.lights) {
    if (l.type == LightType::Point) point = &l;
    if (l.type == LightType::Spot) spot = &l;
    if (l.type == LightType::Directional) sun = &l;
  }
  ASSERT_TRUE(point && spot && sun);
  // The exporter writes float32 JSON numbers: compare to 1e-6 relative.
  const double pointWattsPerSr = 100 / (4 * M_PI), spotWattsPerSr = 50 / (4 * M_PI);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(point->intensity[c], pointWattsPerSr, 1e-6 * pointWattsPerSr);
    EXPECT_NEAR(spot->intensity[c], spotWattsPerSr, 1e-6 * spotWattsPerSr);
    EXPECT_NEAR(sun->irradiance[c], 3.0, 3e-6);
  }
  // Blender's z-up scene is y-up in glTF: the point light at Blender (1, 2, 3) is at (1, 3, -2).
  EXPECT_LT((point->position - Eigen::Vector3d(1, 3, -2)).norm(), 1e-6);
  EXPECT_LT((spot->position - Eigen::Vector3d(0, 2, 0)).norm(), 1e-6);
  // The spot points down; its 60° cone has a 30° outer half-angle and 0.2 blend an inner 24°.
  EXPECT_LT((spot->direction - Eigen::Vector3d(0, -1, 0)).norm(), 1e-6);
  EXPECT_NEAR(spot->cosOuter, std::cos(30 * M_PI / 180), 1e-6);
  EXPECT_NEAR(spot->cosInner, std::cos(24 * M_PI / 180), 1e-6);
  // The sun, turned 30° about Blender's x from straight down (Blender -z), travels along
  // (0, sin 30°, -cos 30°) in Blender; (x, y, z) → (x, z, -y) gives glTF's y-up frame.
  EXPECT_LT((sun->direction - Eigen::Vector3d(0, -std::cos(M_PI / 6), -std::sin(M_PI / 6))).norm(),
            1e-6);
}

TEST(GltfLoader, FirstPerspectiveCameraIsTheDefaultCamera) {
  tinygltf::Model model = quadModel();
  tinygltf::Camera camera;
  camera.type = "perspective";
  camera.perspective.yfov = M_PI / 4;
  camera.perspective.aspectRatio = 1.5;
  camera.perspective.znear = 0.1;
  model.cameras.push_back(camera);
  tinygltf::Node node;
  node.camera = 0;
  node.translation = {0, 1, 5};
  node.rotation = {0, std::sin(M_PI / 4), 0, std::cos(M_PI / 4)};  // looks along -x
  model.nodes.push_back(node);
  model.scenes[0].nodes.push_back(1);
  const std::string path = write(model, "camera.glb");
  const std::optional<Camera> c = loadGltfCamera(path);
  ASSERT_TRUE(c);
  EXPECT_LT((c->position - Eigen::Vector3d(0, 1, 5)).norm(), 1e-12);
  EXPECT_LT(((c->lookAt - c->position).normalized() - Eigen::Vector3d(-1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((c->up.normalized() - Eigen::Vector3d(0, 1, 0)).norm(), 1e-12);
  EXPECT_NEAR(c->vfovDegrees, 45, 1e-12);
  EXPECT_EQ(c->width, std::lround(1.5 * c->height));
  // The scene-camera lookup falls back to it where no camera sidecar exists.
  const std::optional<Camera> found = findSceneCamera(path);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->position, c->position);
  EXPECT_FALSE(loadGltfCamera(write(quadModel(), "no_camera.glb")));
}

// --- bad input -----------------------------------------------------------------------------------

void expectError(const std::string& path, const std::string& pointer) {
  const std::string what = errorOf(path);
  EXPECT_EQ(what.rfind(path + ": " + pointer, 0), 0u) << "expected '" << pointer << "': " << what;
}

TEST(GltfLoader, MissingBufferFileNamesItsPointer) {
  const std::string path = write(quadModel(), "missing_bin.gltf");
  fs::remove(scratchDir() / "missing_bin.bin");
  expectError(path, "/buffers/0/uri: cannot read buffer file");
}

TEST(GltfLoader, AccessorOrBufferViewOutOfRange) {
  tinygltf::Model model = quadModel();
  model.accessors[0].count = 1000;
  expectError(write(model, "long_accessor.glb"), "/accessors/0: 1000 elements");
  model = quadModel();
  model.bufferViews[0].byteLength = 1u << 20;
  expectError(write(model, "long_view.glb"), "/bufferViews/0");
  model = quadModel();
  model.meshes[0].primitives[0].attributes["POSITION"] = 42;
  expectError(write(model, "no_accessor.glb"), "/accessors/42: accessor 42 does not exist");
}

TEST(GltfLoader, IndexPastTheVertices) {
  tinygltf::Model model = quadModel();
  const std::vector<std::uint16_t> bad = {0, 1, 7};
  const int index = static_cast<int>(model.meshes[0].primitives[0].indices);
  model.accessors[index].bufferView = test::addBufferView(model, bad.data(), 6);
  model.accessors[index].count = 3;
  expectError(write(model, "bad_index.glb"), "/accessors/" + std::to_string(index) + ": index 7");
}

TEST(GltfLoader, NonFinitePosition) {
  tinygltf::Model model = quadModel();
  const std::vector<float> positions = {0, 0, 0, NAN, 0, 0, 1, 1, 0, 0, 1, 0};
  model.meshes[0].primitives[0].attributes["POSITION"] =
      test::addAccessor(model, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, TINYGLTF_TYPE_VEC3, 3);
  const int accessor = model.meshes[0].primitives[0].attributes["POSITION"];
  auto& buffer = model.buffers[0].data;
  std::memcpy(&buffer[model.bufferViews[model.accessors[accessor].bufferView].byteOffset + 12],
              &positions[3], 4);
  model.accessors[accessor].minValues.clear();
  model.accessors[accessor].maxValues.clear();
  expectError(write(model, "nan.glb"), "/accessors/" + std::to_string(accessor) + ": element 1");
}

TEST(GltfLoader, UnsupportedRequiredExtensionButUsedOnesAreOnlyNoted) {
  tinygltf::Model model = quadModel();
  model.extensionsUsed = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  EXPECT_EQ(errorOf(write(model, "used.glb")), "");
  model.extensionsRequired = {"KHR_lights_punctual", "KHR_draco_mesh_compression"};
  expectError(write(model, "required.glb"),
              "/extensionsRequired/1: required extension KHR_draco_mesh_compression");
}

// The quad with a base colour texture whose image is the file `uri`.
tinygltf::Model quadWithBaseColourImage(const std::string& uri) {
  tinygltf::Model model = quadModel();
  tinygltf::Image image;
  image.uri = uri;
  model.images.push_back(image);
  tinygltf::Texture texture;
  texture.source = 0;
  model.textures.push_back(texture);
  model.materials[0].pbrMetallicRoughness.baseColorTexture.index = 0;
  return model;
}

// Asked to use the material's colour (the command line's default), an image that does not decode
// is a warning at its JSON pointer, no texture and one fallback; strict, an error as above.
TEST(GltfLoader, ACorruptImageCanFallBackToTheMaterialsColour) {
  tinygltf::Model model = quadWithBaseColourImage("corrupt_fallback.png");
  std::ofstream(scratchDir() / "corrupt_fallback.png") << "not a png";
  const auto path = write(model, "corrupt_fallback.gltf");
  ::testing::internal::CaptureStderr();
  const Scene scene = loadGltfScene(path, UnreadableTextures::UseMaterialColour);
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_FALSE(scene.materials.empty());
  EXPECT_EQ(scene.materials[0].diffuseTexture, -1);
  EXPECT_FALSE(scene.materials[0].alphaFromDiffuse);
  ASSERT_EQ(scene.textureFallbacks.size(), 1u);
  EXPECT_NE(scene.textureFallbacks[0].find("/images/0"), std::string::npos)
      << scene.textureFallbacks[0];
  EXPECT_NE(log.find("/images/0"), std::string::npos) << log;
  EXPECT_NE(errorOf(path).find("corrupt_fallback.png"), std::string::npos);  // strict by default
}

TEST(GltfLoader, MissingAndCorruptImages) {
  tinygltf::Model model = quadWithBaseColourImage("no_such_texture.png");
  expectError(write(model, "missing_image.gltf"), "/images/0/uri: cannot read image file");
  // A file that is there but is not an image: the texture decoder names it.
  std::ofstream(scratchDir() / "corrupt.png") << "not a png";
  model.images[0].uri = "corrupt.png";
  const std::string what = errorOf(write(model, "corrupt_image.gltf"));
  EXPECT_NE(what.find("corrupt.png"), std::string::npos) << what;
  // An image in a buffer view that runs past its buffer (tinygltf would read beyond it).
  model.images[0].uri.clear();
  model.images[0].mimeType = "image/png";
  const std::vector<unsigned char> bytes(16, 0);
  model.images[0].bufferView = test::addBufferView(model, bytes.data(), bytes.size());
  model.bufferViews.back().byteLength = 1u << 20;
  expectError(write(model, "image_view_past_buffer.glb"),
              "/bufferViews/" + std::to_string(model.images[0].bufferView) + ": bytes");
  // Within its buffer but not an image: the decoder names the embedded image.
  model.bufferViews.back().byteLength = bytes.size();
  const std::string embedded = errorOf(write(model, "image_view_zeros.glb"));
  EXPECT_NE(embedded.find("#/images/0"), std::string::npos) << embedded;
}

TEST(GltfLoader, NodeCyclesAndBadJsonAreInputErrors) {
  tinygltf::Model model = quadModel();
  model.nodes[0].children = {0};
  expectError(write(model, "cycle.glb"), "/nodes/0: node is reached twice");
  const fs::path broken = scratchDir() / "broken.gltf";
  std::ofstream(broken) << "{\"asset\": {\"version\": \"2.0\"}, ";
  EXPECT_NE(errorOf(broken).find("not valid glTF JSON"), std::string::npos) << errorOf(broken);
  const fs::path truncated = scratchDir() / "truncated.glb";
  std::ofstream(truncated, std::ios::binary) << std::string("glTF\x02\x00\x00\x00", 8);
  EXPECT_NE(errorOf(truncated).find("shorter than its 20-byte header"), std::string::npos)
      << errorOf(truncated);
}

}  // namespace
}  // namespace rad
