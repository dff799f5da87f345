// The Cornell box read from glTF solves to the same radiosity, element by element, as the OBJ
// scene it was written from: the glTF (tests/support/gltf_writer.h) holds the OBJ's polygons as
// triangles under a node that rotates by 90° and scales by 2, its vertices written through the
// inverse transform, and its emission as colour × KHR_materials_emissive_strength. The OBJ side
// is the same triangles (fanTriangulated) with its positions rounded to float32, as glTF stores
// them; that transform is exact in binary floating point, so both solves mesh the very same
// surfaces and cast the very same seeded rays. (Arbitrary transforms are checked on the geometry,
// to float32 precision, in tests/scene/test_gltf_loader.cpp.)
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>

#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_loader.h"
#include "tests/support/gltf_writer.h"

namespace rad {
namespace {

TEST(GltfSolve, CornellBoxFromGltfSolvesAsTheObj) {
  const Scene obj = loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj");
  Eigen::Matrix4d transform = Eigen::Matrix4d::Zero();  // (x, y, z) → (2z, 2y, −2x)
  transform(0, 2) = 2;
  transform(1, 1) = 2;
  transform(2, 0) = -2;
  transform(3, 3) = 1;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "radiosity_gltf_solve";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "cornell.gltf").string();
  ASSERT_TRUE(test::writeGltf(test::gltfModel(obj, transform), path));

  SolveOptions options;
  options.targetElements = 400;
  options.raysPerElement = 256;
  options.threads = 2;
  options.seed = 7;
  Scene reference = test::fanTriangulated(obj);
  for (Eigen::Vector3d& p : reference.positions) p = p.cast<float>().cast<double>();
  const SolveResult fromObj = solveScene(reference, options);
  const SolveResult fromGltf = solveScene(loadScene(path), options);
  const std::vector<Rgb>& a = fromObj.solution.radiosity;
  const std::vector<Rgb>& b = fromGltf.solution.radiosity;
  ASSERT_EQ(a.size(), b.size());
  double maxB = 0;
  for (const Rgb& v : a) maxB = std::max(maxB, v.maxComponent());
  ASSERT_GT(maxB, 0);
  // The same surfaces, rays and reflectances: what remains is the rounding of the emission,
  // written as colour / strength and read back as colour × strength (a few ulps).
  for (std::size_t e = 0; e < a.size(); ++e)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[e][c], b[e][c], 1e-12 * maxB) << "element " << e;
}

}  // namespace
}  // namespace rad
