// Relight (solve --keep-factors, then relight): the radiosity system B = E + ρ F B depends on the
// materials and lights only through E and ρ, so a kept solve solved again with other colours,
// emission and light strengths must equal a fresh solve of the scene so changed — the kept rows
// are the very rows the fresh solve casts (sourceRayMultipliers), and E_d scales with the light.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/relight.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

std::vector<Light> lamps(const Rgb& spotScale = Rgb::all(1), const Rgb& pointScale = Rgb::all(1)) {
  Light spot;
  spot.type = LightType::Spot;
  spot.position = {0.15, 0.5, 0.45};
  spot.direction = Eigen::Vector3d(0.1, -1, -0.1).normalized();
  spot.intensity = Rgb{0.05, 0.15, 0.3} * spotScale;
  spot.cosOuter = std::cos(35 * M_PI / 180);
  spot.cosInner = std::cos(25 * M_PI / 180);
  spot.group = "lamp";
  Light point;
  point.type = LightType::Point;
  point.position = {0.45, 0.45, 0.1};
  point.intensity = Rgb{0.3, 0.18, 0.06} * pointScale;
  return {spot, point};
}

SolveOptions keepOptions() {
  SolveOptions o;
  o.scenePath = kCornell;
  o.targetElements = 300;
  o.raysPerElement = 64;
  o.threads = 2;
  o.tolerance = 1e-10;
  o.maxIterations = 1000000;
  o.keepFactors = true;
  return o;
}

// The changes relight is asked for: the red wall blue, the ceiling light dimmer and bluish, the
// spot × 3, the point light's colour warmer.
const Rgb kRed{0.15, 0.25, 0.7}, kCeiling{6, 7, 9}, kSpot = Rgb::all(3), kPoint{1, 0.5, 0.2};

void changeMaterials(Scene& scene) {
  for (Material& m : scene.materials) {
    if (m.name == "red") m.diffuse = kRed;
    if (m.name == "light") m.emission = kCeiling;
  }
}

double peak(const std::vector<Rgb>& v) {
  double p = 0;
  for (const Rgb& c : v) p = std::max(p, c.maxComponent());
  return p;
}

struct Kept {
  SolveResult solve;
  KeptFactors factors;
};

const Kept& keptCornell() {
  static const Kept kept = [] {
    Scene scene = loadScene(kCornell);
    scene.lights = lamps();
    Kept k;
    k.solve = solveScene(std::move(scene), keepOptions());
    k.factors = *k.solve.kept;
    return k;
  }();
  return kept;
}

// The kept scene as relight loads it: the lamps were given in memory, not by a lights file.
Scene keptScene(const KeptFactors& kept) {
  Scene scene = loadKeptScene(kept);
  EXPECT_TRUE(scene.lights.empty());
  scene.lights = lamps();
  return scene;
}

TEST(Relight, EqualsAFreshSolveOfTheChangedSceneAndCastsNoRay) {
  const Kept& kept = keptCornell();
  ASSERT_EQ(kept.factors.rows.size(), kept.factors.area.size());
  ASSERT_EQ(kept.factors.lightIrradiance.size(), 2u);
  EXPECT_GT(kept.solve.report.raysCast, 0u);

  Scene changed = loadScene(kCornell);
  changeMaterials(changed);
  changed.lights = lamps(kSpot, kPoint);
  const SolveResult fresh = solveScene(std::move(changed), keepOptions());

  Scene relitScene = keptScene(kept.factors);
  changeMaterials(relitScene);
  const SolveResult relit =
      relightScene(kept.factors, "kept", std::move(relitScene), {kSpot, kPoint}, keepOptions());
  EXPECT_EQ(relit.report.raysCast, 0u);
  EXPECT_EQ(relit.report.directLightRays, 0u);
  EXPECT_EQ(relit.report.rowsComputed, 0);
  ASSERT_TRUE(relit.report.converged);
  const std::vector<Rgb>& a = fresh.solution.radiosity;
  const std::vector<Rgb>& b = relit.solution.radiosity;
  ASSERT_EQ(a.size(), b.size());
  // Both converged to 1e-10 of the emitted power over the same rows: equal to that order. The
  // change itself is far larger (the red wall turned blue).
  const double scale = peak(a);
  double changedMost = 0;
  for (size_t e = 0; e < a.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(b[e][c], a[e][c], 1e-7 * scale) << "element " << e;
      changedMost = std::max(changedMost, std::abs(b[e][c] - kept.solve.solution.radiosity[e][c]));
    }
  EXPECT_GT(changedMost, 0.05 * scale);
}

TEST(Relight, FromTheFileEqualsFromMemoryToTheFactorsFloatRounding) {
  const Kept& kept = keptCornell();
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("radiosity_relight_" + std::to_string(::getpid()) + ".bin");
  {
    std::ofstream out(file, std::ios::binary);
    writeKeptFactors(out, kept.factors);
  }
  const KeptFactors read = readKeptFactors(file.string());
  std::filesystem::remove(file);
  const std::vector<Rgb> scales{Rgb::all(1), Rgb::all(1)};
  const SolveResult fromMemory =
      relightScene(kept.factors, "kept", keptScene(kept.factors), scales, keepOptions());
  const SolveResult fromFile = relightScene(read, "kept", keptScene(read), scales, keepOptions());
  // Unchanged inputs: the kept solve's own answer back. The file holds the factors as floats
  // (relative rounding 6e-8), which moves B by about that much.
  const double scale = peak(kept.solve.solution.radiosity);
  for (size_t e = 0; e < fromFile.solution.radiosity.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(fromMemory.solution.radiosity[e][c], kept.solve.solution.radiosity[e][c],
                  1e-7 * scale);
      ASSERT_NEAR(fromFile.solution.radiosity[e][c], kept.solve.solution.radiosity[e][c],
                  1e-5 * scale);
    }
}

TEST(Relight, RefusesAChangedGeometryAndAnEmptyScene) {
  const Kept& kept = keptCornell();
  Scene moved = keptScene(kept.factors);
  moved.positions[0].x() += 0.01;
  EXPECT_THROW(relightScene(kept.factors, "kept", std::move(moved), {Rgb::all(1), Rgb::all(1)},
                            keepOptions()),
               InputError);
  Scene dark = keptScene(kept.factors);
  for (Material& m : dark.materials) m.emission = Rgb();
  EXPECT_THROW(relightScene(kept.factors, "kept", std::move(dark), {Rgb(), Rgb()}, keepOptions()),
               InputError);
}

// The lights' first shot is kept, not cast again: lights that moved, or whose strength changed in
// the scene's files rather than by an override's scale, or a different number of them, no longer
// fit it.
TEST(Relight, RefusesLightsThatChangedSinceTheSolve) {
  const Kept& kept = keptCornell();
  const std::vector<Rgb> scales{Rgb::all(1), Rgb::all(1)};
  Scene moved = keptScene(kept.factors);
  moved.lights[1].position.x() += 0.01;
  EXPECT_THROW(relightScene(kept.factors, "kept", std::move(moved), scales, keepOptions()),
               InputError);
  Scene brighter = keptScene(kept.factors);
  brighter.lights[0].intensity = brighter.lights[0].intensity * 2;
  EXPECT_THROW(relightScene(kept.factors, "kept", std::move(brighter), scales, keepOptions()),
               InputError);
  Scene fewer = keptScene(kept.factors);
  fewer.lights.pop_back();
  EXPECT_THROW(relightScene(kept.factors, "kept", std::move(fewer), scales, keepOptions()),
               InputError);
  // The same lights scaled by the override: accepted, and the relit scene's lights are scaled.
  const SolveResult relit =
      relightScene(kept.factors, "kept", keptScene(kept.factors), {kSpot, kPoint}, keepOptions());
  const std::vector<Light> expected = lamps(kSpot, kPoint);
  for (size_t l = 0; l < expected.size(); ++l)
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(relit.solution.scene.lights[l].intensity[c], expected[l].intensity[c]);
}

TEST(Relight, KeepFactorsNeedsHemisphereRowsOnAUniformMesh) {
  SolveOptions o = keepOptions();
  o.formFactors = FormFactorMethod::Analytic;
  EXPECT_THROW(validateSolveOptions(o), InputError);
  o = keepOptions();
  o.lightGroups = true;
  EXPECT_THROW(validateSolveOptions(o), InputError);
}

}  // namespace
}  // namespace rad
