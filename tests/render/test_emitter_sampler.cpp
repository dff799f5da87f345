// Emitter sampling from one 2D point (EmitterSampler::sample(u, v)): the element is chosen by
// power and the rescaled u goes on to place the point, so a stratified (u, v) set must spread
// uniformly over the whole emitting area, with the density pdfArea() states.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/render/emitter_sampler.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

TEST(EmitterSampler, TwoDimensionalSamplesCoverTheEmittersUniformly) {
  // The Cornell light (0.13 × 0.105 m, uniform Ke) split into elements of unequal areas.
  const Scene scene =
      loadObjScene(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj");
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(mesh.totalArea() / 300);
  const EmitterSampler lights(scene, mesh);
  ASSERT_GT(lights.count(), 2);

  // A midpoint grid of N² points: the mean position is the light's centroid and the fraction
  // on each element is its share of the area, both to O(1/N).
  constexpr int kN = 400;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::vector<double> hits(mesh.elementCount(), 0.0);
  double emitterArea = 0;
  for (int e = 0; e < mesh.elementCount(); ++e)
    emitterArea += lights.pdfArea(e) > 0 ? mesh.area(e) : 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      const EmitterSample s = lights.sample((i + 0.5) / kN, (j + 0.5) / kN);
      ASSERT_GE(s.element, 0);
      EXPECT_NEAR(s.pdfArea, 1.0 / emitterArea, 1e-9 / emitterArea);
      EXPECT_NEAR(s.position.y(), 0.5487, 1e-12);
      mean += s.position / (kN * kN);
      hits[s.element] += 1.0 / (kN * kN);
    }
  EXPECT_NEAR(mean.x(), 0.5 * (0.213 + 0.343), 0.13 * 2.0 / kN);
  EXPECT_NEAR(mean.z(), 0.5 * (0.227 + 0.332), 0.105 * 2.0 / kN);
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (lights.pdfArea(e) > 0) {
      EXPECT_NEAR(hits[e], mesh.area(e) / emitterArea, 2.0 / kN) << e;
    }
}

}  // namespace
}  // namespace rad
