// Shooter selection in O(log n) (MaxPowerTree): the same choice a linear scan makes (largest
// key, lowest index on ties) and the same total, under random updates; and progressive shooting
// on the Cornell box shoots, at every step, the shooter holding the most unshot power.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "radiosity/solvers/max_power_tree.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

// The scan the tree replaces: first index with the largest key > 0, or -1.
int scanArgmax(const std::vector<double>& keys) {
  int best = -1;
  double bestKey = 0;
  for (size_t i = 0; i < keys.size(); ++i)
    if (keys[i] > bestKey) {
      bestKey = keys[i];
      best = static_cast<int>(i);
    }
  return best;
}

TEST(MaxPowerTree, AgreesWithLinearScanUnderRandomUpdates) {
  std::mt19937 rng(7);
  for (size_t n : {1u, 2u, 3u, 5u, 64u, 1000u}) {
    MaxPowerTree tree(n);
    std::vector<double> keys(n, 0.0);
    EXPECT_EQ(tree.argmax(), -1);
    EXPECT_EQ(tree.total(), 0.0);
    for (int step = 0; step < 5000; ++step) {
      const size_t i = rng() % n;
      // Few distinct values, many ties and zeros: the tie-break is what keeps the shooting order.
      const double key = (rng() % 4 == 0) ? 0.0 : static_cast<double>(rng() % 8) * 0.125;
      keys[i] = key;
      tree.set(i, key);
      // A batch of deferred changes too (duplicates included), as a shot makes them.
      for (int b = 0; b < 3; ++b) {
        const size_t j = rng() % n;
        keys[j] = static_cast<double>(rng() % 8) * 0.125;
        tree.setLater(j, keys[j]);
      }
      tree.update();
      ASSERT_EQ(tree.argmax(), scanArgmax(keys)) << "n " << n << " step " << step;
      double sum = 0;
      for (double k : keys) sum += k;
      ASSERT_NEAR(tree.total(), sum, 1e-12 * std::max(1.0, sum));
    }
  }
}

TEST(MaxPowerTree, EmptyAndReset) {
  MaxPowerTree tree;
  EXPECT_EQ(tree.argmax(), -1);
  EXPECT_EQ(tree.total(), 0.0);
  tree.reset(3);
  tree.set(2, 1.5);
  tree.set(0, 1.5);
  EXPECT_EQ(tree.argmax(), 0);  // tie: lowest index
  EXPECT_DOUBLE_EQ(tree.total(), 3.0);
  tree.reset(3);
  EXPECT_EQ(tree.argmax(), -1);
}

TEST(ProgressiveShooting, EachShotTakesTheLargestUnshotPower) {
  const Scene scene = loadObjScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj");
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(mesh.totalArea() / 300);
  const RayCaster rays(mesh);
  const HemisphereFormFactors method(mesh, rays, {64, 1});
  FormFactorCache cache(method);
  const RadiosityProblem problem = makeProblem(scene, mesh);
  ProgressiveSolver solver(problem, cache);
  for (int step = 0; step < 2000 && solver.progress() > 1e-6; ++step) {
    // Elements shoot for themselves here, so their unshot power is the shooters'.
    const std::vector<Rgb> unshot = solver.unshotPowerOfElements();
    std::vector<double> keys(unshot.size());
    double total = 0;
    for (size_t i = 0; i < unshot.size(); ++i) {
      keys[i] = std::fabs(unshot[i].r) + std::fabs(unshot[i].g) + std::fabs(unshot[i].b);
      total += keys[i];
    }
    ASSERT_NEAR(solver.progress(), total / problem.emittedPower(),
                1e-12 * (total / problem.emittedPower()));
    const int expected = scanArgmax(keys);
    solver.step();
    ASSERT_EQ(solver.lastShooter(), expected) << "step " << step;
  }
  EXPECT_LT(solver.progress(), 1e-2);  // it did get somewhere
}

}  // namespace
}  // namespace rad
