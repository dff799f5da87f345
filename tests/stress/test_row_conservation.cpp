// Energy conservation of every form-factor row: a row can never send out more than the element
// emits (sum_j F_ij <= 1), and in a closed scene with no reachable back face nothing escapes
// (sum_j F_ij = 1). Checked for hemisphere rows in open, closed, degenerate and specular scenes,
// and for analytic element-to-patch rows in a closed convex box, where the exact
// point-to-polygon factors of the tiling patches add up to 1 at every receiver point.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "radiosity/core/log.h"
#include "radiosity/formfactors/analytic_patch_shots.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "radiosity/visibility/ray_caster.h"
#include "tests/stress/stress_scenes.h"

namespace rad {
namespace {

struct RowSums {
  double largest = 0, smallest = INFINITY;
  int rows = 0;
};

// Every row of the scene's hemisphere form factors; checks the per-row bookkeeping on the way.
RowSums hemisphereRowSums(const std::string& path, int elements, int rays) {
  setLogLevel(LogLevel::Quiet);
  const Scene scene = loadObjScene(path);
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(mesh.totalArea() / elements);
  const RayCaster caster(mesh);
  HemisphereOptions options{rays, 5};
  if (scene.hasSpecular()) options.specular = specularSurfaces(scene, mesh);
  const HemisphereFormFactors method(mesh, caster, options);
  RowSums sums;
  for (int i = 0; i < mesh.elementCount(); ++i) {
    const FormFactorRow row = method.computeRow(i);
    double sum = 0;
    Rgb tinted;
    for (size_t k = 0; k < row.targets.size(); ++k) {
      EXPECT_TRUE(std::isfinite(row.values[k]) && row.values[k] >= 0) << "row " << i;
      EXPECT_NE(row.targets[k], i) << "a flat element sees itself";
      sum += row.values[k];
      tinted += row.factor(k);
    }
    // Untinted values count rays: with the escaped part they account for every ray cast.
    EXPECT_NEAR(sum + row.escaped, 1.0, 1e-12) << "row " << i;
    for (int c = 0; c < 3; ++c)
      EXPECT_LE(tinted[c], sum + 1e-12) << "specular tint above 1, row " << i;
    sums.largest = std::max(sums.largest, sum);
    sums.smallest = std::min(sums.smallest, sum);
    ++sums.rows;
  }
  return sums;
}

TEST(RowConservation, OpenCornellBoxRowsNeverExceedOne) {
  const RowSums s = hemisphereRowSums(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj", 800, 256);
  EXPECT_LE(s.largest, 1 + 1e-12);
  EXPECT_LT(s.smallest, 1.0) << "the box is open at the front: some rows must lose rays";
}

TEST(RowConservation, MirrorAndGlassRowsNeverExceedOne) {
  const RowSums s =
      hemisphereRowSums(RADIOSITY_DATA_DIR "/cornell_box/cornell_box_mirror_glass.obj", 800, 256);
  EXPECT_LE(s.largest, 1 + 1e-12);
}

TEST(RowConservation, ClosedFurnaceRowsSumToOne) {
  const RowSums s = hemisphereRowSums(RADIOSITY_DATA_DIR "/tests/furnace_box.obj", 600, 256);
  EXPECT_GE(s.smallest, 1 - 1e-12);
  EXPECT_LE(s.largest, 1 + 1e-12);
}

// Slivers, a thin plate, coincident faces and a tiny emitter: still closed, so no ray may slip
// through a crack or start behind a surface.
TEST(RowConservation, ClosedDegenerateRoomRowsSumToOne) {
  const RowSums s = hemisphereRowSums(testing::writeHostileRoom(0.5), 600, 512);
  std::cout << s.rows << " rows, sums in [" << s.smallest << ", " << s.largest << "]\n";
  EXPECT_GE(s.smallest, 1 - 1e-12);
  EXPECT_LE(s.largest, 1 + 1e-12);
}

TEST(RowConservation, AnalyticRowsOfAClosedConvexBoxSumToOne) {
  setLogLevel(LogLevel::Quiet);
  const Scene scene = loadObjScene(RADIOSITY_DATA_DIR "/tests/furnace_box.obj");
  PatchMesh mesh = buildPatchMesh(scene);
  mesh.subdivideUniform(0.25);
  mesh.markShooters();
  mesh.subdivideUniform(0.02);
  const RayCaster caster(mesh);
  AnalyticPatchShots shots(mesh, caster, AnalyticOptions{3, 16, 7});
  const auto f = shots.gatheringMatrix();
  double worst = 0;
  for (int i = 0; i < f.outerSize(); ++i) {
    double sum = 0;
    for (decltype(f)::InnerIterator it(f, i); it; ++it) {
      ASSERT_TRUE(std::isfinite(it.value()) && it.value() >= 0);
      sum += it.value();
    }
    worst = std::max(worst, std::fabs(sum - 1));
  }
  std::cout << "analytic rows: largest |sum − 1| = " << worst << "\n";
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace rad
