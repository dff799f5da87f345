// Light groups (--light-groups): which emitters and lights form each group, and the solve's
// layers. The radiosity system is linear in E, so (1) the layers add up to the whole solution and
// to an ungrouped solve of the same scene, and (2) scaling one group's emission scales its layer
// by the same factor and leaves the others as they were.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/light_groups.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

Light spot(double scale = 1) {
  Light l;
  l.type = LightType::Spot;
  l.position = {0.15, 0.5, 0.45};
  l.direction = Eigen::Vector3d(0.1, -1, -0.1).normalized();
  l.intensity = Rgb{0.05, 0.15, 0.3} * scale;
  l.cosOuter = std::cos(35 * M_PI / 180);
  l.cosInner = std::cos(25 * M_PI / 180);
  l.group = "lamp";
  return l;
}

Light point() {
  Light l;
  l.type = LightType::Point;
  l.position = {0.45, 0.45, 0.1};
  l.intensity = {0.3, 0.18, 0.06};
  return l;
}

// The Cornell box (its ceiling light is the material "light") with a spot in group "lamp" and an
// ungrouped point light; `lampScale` and `ceilingScale` scale the spot and the ceiling's Ke.
Scene litCornell(double lampScale = 1, double ceilingScale = 1) {
  Scene scene = loadScene(kCornell);
  scene.lights = {spot(lampScale), point()};
  for (Material& m : scene.materials)
    if (m.isEmitter()) m.emission = m.emission * ceilingScale;
  return scene;
}

TEST(LightGroups, EachEmitterAndLightFormsAGroupUnlessItNamesOne) {
  Scene scene = litCornell();
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = Rgb::all(1);
  sky.group = "light";  // joins the ceiling's material group by its name
  scene.lights.push_back(sky);
  Light second = spot();  // a second spot in "lamp"
  scene.lights.push_back(second);
  const std::vector<LightGroup> groups = lightGroups(scene);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].name, "light");
  ASSERT_EQ(groups[0].materials.size(), 1u);
  EXPECT_EQ(scene.materials[groups[0].materials[0]].name, "light");
  EXPECT_EQ(groups[0].lights, (std::vector<size_t>{2}));
  EXPECT_EQ(groups[1].name, "lamp");
  EXPECT_EQ(groups[1].lights, (std::vector<size_t>{0, 3}));
  EXPECT_EQ(groups[2].name, "point1");  // unnamed: its type and index
  EXPECT_EQ(groups[2].lights, (std::vector<size_t>{1}));
  EXPECT_TRUE(groups[2].materials.empty());
}

TEST(LightGroups, NamesBecomeSafeFileNamesAndAClashIsAnError) {
  Scene scene = litCornell();
  scene.lights[0].group = "desk lamp/2";
  std::vector<LightGroup> groups = lightGroups(scene);
  EXPECT_EQ(groups[1].fileName, "desk_lamp_2");
  scene.lights[1].group = "desk_lamp_2";  // another group, the same file name
  EXPECT_THROW(lightGroups(scene), InputError);
  scene.lights[1].group = "..";
  groups = lightGroups(scene);
  EXPECT_EQ(groups[2].fileName, "__");  // never a directory's name
}

SolveOptions quick(FormFactorMethod method) {
  SolveOptions o;
  o.targetElements = 400;
  o.raysPerElement = 128;
  o.threads = 2;
  o.formFactors = method;
  o.shadowRays = 4;
  o.tolerance = 1e-9;
  o.maxIterations = 200000;
  return o;
}

double maxOf(const std::vector<Rgb>& v) {
  double m = 0;
  for (const Rgb& c : v) m = std::max(m, c.maxComponent());
  return m;
}

TEST(LightGroups, LayersSumToTheWholeAndToAnUngroupedSolve) {
  // Analytic factors: the same shadow rays with and without groups, and the first shot keeps each
  // light's random numbers, so the two solves differ only by the solver's tolerance (1e-9).
  SolveOptions grouped = quick(FormFactorMethod::Analytic);
  grouped.lightGroups = true;
  const SolveResult layered = solveScene(litCornell(), grouped);
  const SolveResult whole = solveScene(litCornell(), quick(FormFactorMethod::Analytic));
  const Solution& s = layered.solution;
  ASSERT_EQ(s.layers.size(), 3u);
  ASSERT_TRUE(layered.report.converged);
  const double scale = maxOf(whole.solution.radiosity);
  ASSERT_GT(scale, 0);
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    Rgb sum;
    for (const LightLayer& layer : s.layers) sum += layer.radiosity[e];
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(sum[c], s.radiosity[e][c], 1e-12 * scale);
      EXPECT_NEAR(s.radiosity[e][c], whole.solution.radiosity[e][c], 1e-6 * scale)
          << "element " << e;
    }
    for (int k = 0; k < 3; ++k) {
      Rgb pointSum;
      for (const LightLayer& layer : s.layers) pointSum += layer.pointRadiosity[e][k];
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(pointSum[c], s.pointRadiosity[e][k][c], 1e-12 * scale);
        EXPECT_NEAR(s.pointRadiosity[e][k][c], whole.solution.pointRadiosity[e][k][c],
                    1e-6 * scale);
      }
    }
  }
  // Every layer carries light: none is the whole, none is empty.
  for (const LightLayer& layer : s.layers) {
    EXPECT_GT(maxOf(layer.radiosity), 1e-3 * scale) << layer.group.name;
    EXPECT_LT(maxOf(layer.radiosity), scale) << layer.group.name;
  }
}

TEST(LightGroups, ScalingOneGroupScalesItsLayerAndLeavesTheOthers) {
  // Hemisphere rows: their rays per emitter row come from each group's own shares, so scaling a
  // group changes no row. k = 3 is not a power of two: the products round.
  const double k = 3;
  for (const bool scaleCeiling : {false, true}) {
    SolveOptions o = quick(FormFactorMethod::Hemisphere);
    o.lightGroups = true;
    const SolveResult base = solveScene(litCornell(), o);
    const SolveResult scaled = solveScene(scaleCeiling ? litCornell(1, k) : litCornell(k, 1), o);
    const size_t changed = scaleCeiling ? 0 : 1;  // "light" (the ceiling) or "lamp"
    ASSERT_EQ(base.solution.layers.size(), 3u);
    ASSERT_EQ(scaled.solution.layers.size(), 3u);
    for (size_t g = 0; g < 3; ++g) {
      const auto& a = base.solution.layers[g].radiosity;
      const auto& b = scaled.solution.layers[g].radiosity;
      const double factor = g == changed ? k : 1;
      const double scale = maxOf(a);
      for (size_t e = 0; e < a.size(); ++e)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(b[e][c], factor * a[e][c], 1e-12 * factor * scale)
              << "group " << base.solution.layers[g].group.name << ", element " << e;
    }
  }
}

TEST(LightGroups, RefinementIsRefusedWithGroups) {
  SolveOptions o = quick(FormFactorMethod::Analytic);
  o.lightGroups = true;
  o.refineThreshold = 0.1;
  EXPECT_THROW(validateSolveOptions(o), InputError);
}

}  // namespace
}  // namespace rad
