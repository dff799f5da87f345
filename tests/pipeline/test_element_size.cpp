// Which rule sets the element size, and what the mesh stage makes of it: the scene default
// keeps the Cornell box's old mesh and is the same for the scene scaled by 1000; --elements is
// met within 20%, and large surfaces are split on where small triangles took the count; slivers
// come out under the aspect bound; analytic factors on a scene of many polygons are refused before
// any work.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/element_size.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

Scene cornellBox() { return loadScene(kCornell); }

int elementsFor(const Scene& scene, const SolveOptions& options) {
  return meshScene(scene, options).mesh->elementCount();
}

// Adds an n × n grid of quads of side `side` in the y = 0 plane, facing up, each a polygon.
Scene gridScene(int n, double side) {
  Scene scene;
  scene.sourcePath = "grid";
  Material grey;
  grey.name = "grey";
  grey.diffuse = Rgb(0.5, 0.5, 0.5);
  scene.materials.push_back(grey);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) scene.positions.push_back({i * side, 0, j * side});
  const auto at = [n](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      ScenePolygon quad;
      quad.vertices = std::vector<int>{at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)};
      scene.polygons.push_back(quad);
    }
  return scene;
}

// Adds the quad of the four corners, in order, as one polygon.
void addQuad(Scene& scene, const std::array<Eigen::Vector3d, 4>& corners) {
  const int base = static_cast<int>(scene.positions.size());
  for (const Eigen::Vector3d& p : corners) scene.positions.push_back(p);
  ScenePolygon quad;
  quad.vertices = std::vector<int>{base, base + 1, base + 2, base + 3};
  scene.polygons.push_back(quad);
}

TEST(ElementSize, EachOptionNamesItsRule) {
  SolveOptions o;
  EXPECT_EQ(decideElementSize(o, 2, 3).rule, ElementSizeRule::SceneDefault);
  o.targetElements = 100;
  const ElementSizing byCount = decideElementSize(o, 2, 3);
  EXPECT_EQ(byCount.rule, ElementSizeRule::Elements);
  EXPECT_EQ(byCount.targetCount, 100);
  // S is the edge of the equilateral triangle of the mean area: S²√3/4 = 2 / 100.
  EXPECT_NEAR(byCount.edge * byCount.edge * std::sqrt(3.0) / 4, 0.02, 1e-15);
  o.targetElements = 0;
  o.elementSize = 0.5;
  const ElementSizing bySize = decideElementSize(o, 2, 3);
  EXPECT_EQ(bySize.rule, ElementSizeRule::ElementSize);
  EXPECT_NEAR(bySize.maxArea, 0.25 * std::sqrt(3.0) / 4, 1e-15);
  o.maxArea = 0.1;
  EXPECT_EQ(decideElementSize(o, 2, 3).rule, ElementSizeRule::MaxArea);
  EXPECT_EQ(elementSizeRuleName(ElementSizeRule::SceneDefault), "scene");
}

TEST(ElementSize, SceneDefaultKeepsTheCornellBoxMesh) {
  // The old default: bisection until no element exceeds total area / 1500.
  const Scene scene = cornellBox();
  PatchMesh old = buildPatchMesh(scene);
  old.subdivideUniform(old.totalArea() / 1500);
  const int now = elementsFor(scene, SolveOptions());
  EXPECT_GE(now, 0.7 * old.elementCount());
  EXPECT_LE(now, 1.3 * old.elementCount());
}

TEST(ElementSize, SceneDefaultIsTheSameForTheSceneScaledBy1000) {
  Scene scene = cornellBox();
  const int original = elementsFor(scene, SolveOptions());
  for (auto& p : scene.positions) p *= 1000;
  EXPECT_EQ(elementsFor(scene, SolveOptions()), original);
  // A bigger room of the same shape gets the same mesh; a finer grid in it does not change S.
  const Scene small = gridScene(10, 0.1), large = gridScene(10, 100);
  EXPECT_EQ(elementsFor(small, SolveOptions()), elementsFor(large, SolveOptions()));
}

TEST(ElementSize, RequestedCountsAreMetWithin20Percent) {
  const Scene cornell = cornellBox();
  for (int count : {300, 1500, 6000}) {
    SolveOptions o;
    o.targetElements = count;
    const int got = elementsFor(cornell, o);
    EXPECT_GE(got, 0.8 * count) << count;
    EXPECT_LE(got, 1.2 * count) << count;
  }
  // A long thin quad (its slivers split first) and a scene of 800 small triangles.
  Scene thin = gridScene(1, 1);
  for (auto& p : thin.positions) p.x() *= 40;
  Scene many = gridScene(20, 0.05);
  for (const Scene* scene : {&thin, &many})
    for (int count : {1000, 4000}) {
      SolveOptions o;
      o.targetElements = count;
      const int got = elementsFor(*scene, o);
      EXPECT_GE(got, 0.8 * count) << scene->polygons.size() << " polygons, " << count;
      EXPECT_LE(got, 1.2 * count) << scene->polygons.size() << " polygons, " << count;
    }
}

TEST(ElementSize, LargeSurfacesAreSplitWhenSmallTrianglesTookTheCount) {
  // 3200 tiny triangles (a 40 × 40 grid of 0.01 quads) beside a 4 × 4 floor of two: at
  // --elements 1000 the count is taken before the floor is touched, yet no element may stay
  // above twice the mean a mesh of 1000 equal elements would have.
  Scene scene = gridScene(40, 0.01);
  for (auto& p : scene.positions) p.y() = 1;  // out of the floor's plane, facing it
  addQuad(scene, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 4), Eigen::Vector3d(4, 0, 4),
                  Eigen::Vector3d(4, 0, 0)});  // the floor
  SolveOptions o;
  o.targetElements = 1000;
  const MeshedScene meshed = meshScene(scene, o);
  const PatchMesh& mesh = *meshed.mesh;
  const double bound = kCountedMaxAreaOverMean * mesh.totalArea() / 1000;
  int floorElements = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    EXPECT_LE(mesh.area(e), bound * (1 + 1e-12)) << "element " << e;
    floorElements += std::fabs(mesh.centroid(e).y()) < 1e-12;
  }
  // Bisection to the bound leaves pieces between half and all of it.
  EXPECT_GE(floorElements, 16 / bound);
  EXPECT_LE(meshed.maxArea, bound * (1 + 1e-12));
}

TEST(ElementSize, SliversAreSplitEvenWhenSmallerThanTheElementArea) {
  // A 4 × 0.1 strip beside a 4 × 4 floor: its two triangles are far below the element area
  // (total / 5000), yet its elements must come out well shaped down to S. (The floor's
  // triangles along it may stay thin fans: see PatchMesh::splitSlivers.)
  Scene scene = gridScene(1, 4);
  addQuad(scene, {Eigen::Vector3d(0, 0, 4), Eigen::Vector3d(0, 0, 4.1), Eigen::Vector3d(4, 0, 4.1),
                  Eigen::Vector3d(4, 0, 4)});  // the strip
  SolveOptions o;
  o.targetElements = 5000;
  const MeshedScene meshed = meshScene(scene, o);
  const PatchMesh& mesh = *meshed.mesh;
  const double minEdge = meshed.sizing.edge / kSliverEdgeFraction;
  ASSERT_LT(minEdge, 0.1);  // so the strip can be cut into well-shaped pieces
  int stripElements = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.patch(e) != 1) continue;
    // The size subdivision that follows bisects some of the strip's pieces (area 0.005 against
    // 0.0033), and longest-edge bisection at worst halves a triangle's smallest angle: twice
    // the bound, no more.
    EXPECT_LE(mesh.aspectRatio(e), 2 * kMaxAspectRatio) << "element " << e;
    ++stripElements;
  }
  EXPECT_GE(stripElements, 4 / 0.1);
}

TEST(ElementSize, AnalyticFactorsOnManyPolygonsAreRefusedWithAnEstimate) {
  SolveOptions o;
  o.formFactors = FormFactorMethod::Analytic;
  try {
    meshScene(gridScene(100, 0.1), o);  // 20000 triangles, each at least one patch
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("impractical"), std::string::npos) << message;
    EXPECT_NE(message.find("hours"), std::string::npos) << message;
    EXPECT_NE(message.find("--form-factors hemisphere"), std::string::npos) << message;
  }
  // The Cornell box stays well inside the limit.
  EXPECT_GT(elementsFor(cornellBox(), o), 0);
}

}  // namespace
}  // namespace rad
