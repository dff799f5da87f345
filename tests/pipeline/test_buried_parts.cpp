// Buried parts of elements (radiosity/visibility/element_exposure.h): a box standing on a floor
// hides part of the floor's elements. The probes find the hidden share of each floor triangle
// (known from the geometry), and in a furnace (every surface emitting E and reflecting ρ inside a
// closed room) every element that is not wholly buried reaches B = E / (1 − ρ): an element
// straddling the box's edge neither loses the rays its hidden part would shoot into the box nor
// spreads its light over the hidden part.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "meshing/patch_mesh.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/solver_factory.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

// A one-sided box without a bottom, its faces looking out: x in [x0, x1], y in [y0, y1], z in
// [0, h], standing on z = 0. Appended to `points` and `faces` as quads.
void addOpenBottomBox(std::vector<Eigen::Vector3d>& p, std::vector<std::vector<int>>& faces,
                      double x0, double x1, double y0, double y1, double h) {
  const int b = static_cast<int>(p.size());
  for (double z : {0.0, h}) {
    p.push_back({x0, y0, z});
    p.push_back({x1, y0, z});
    p.push_back({x1, y1, z});
    p.push_back({x0, y1, z});
  }
  faces.push_back({b + 4, b + 5, b + 6, b + 7});  // top, +z
  faces.push_back({b + 0, b + 1, b + 5, b + 4});  // -y
  faces.push_back({b + 1, b + 2, b + 6, b + 5});  // +x
  faces.push_back({b + 2, b + 3, b + 7, b + 6});  // +y
  faces.push_back({b + 3, b + 0, b + 4, b + 7});  // -x
}

TEST(ElementExposure, FindsTheShareOfEachFloorTriangleUnderABox) {
  // Floor [0, 2]² split along its diagonal into (0,0)-(2,0)-(2,2) and (0,0)-(2,2)-(0,2); the box
  // covers x < 1: a quarter of the first triangle, three quarters of the second. A second floor
  // far from the box is wholly exposed.
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                                    {5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}};
  std::vector<std::vector<int>> faces = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6, 7}};
  addOpenBottomBox(p, faces, 0, 1, 0, 2, 1);
  std::vector<PatchPolygon> polygons;
  for (const auto& f : faces) polygons.push_back({f, 0});
  const PatchMesh mesh(p, polygons);
  const RayCaster rays(mesh);
  // One-sided: the caster built from the mesh alone sees both sides; the probes tell front from
  // back by the element's normal.
  const ElementExposure exposure(mesh, rays);
  // Elements 0 and 1 are the two floor triangles (one element per triangle input).
  ASSERT_EQ(mesh.patch(0), 0);
  ASSERT_EQ(mesh.patch(1), 1);
  // The 8×8 cells resolve the box's edge to within the cells it crosses (about 8 of 64, each
  // counted whole on one side): a tolerance of 4 cells.
  const double cells = 4.0 / 64;
  EXPECT_NEAR(exposure.exposedFraction(0), 0.75, cells);
  EXPECT_NEAR(exposure.exposedFraction(1), 0.25, cells);
  for (int e = 2; e < mesh.elementCount(); ++e) {
    EXPECT_EQ(exposure.buriedCells(e), 0u) << "element " << e << " (patch " << mesh.patch(e) << ")";
    EXPECT_EQ(exposure.exposedFraction(e), 1.0);
  }
  EXPECT_EQ(exposure.partlyBuried(), 2);
  EXPECT_EQ(exposure.fullyBuried(), 0);
  EXPECT_NEAR(exposure.buriedArea(), 2.0, 4 * cells * 2);  // the box's footprint, 1 × 2
}

// A closed room [0, 4]³ looking in, every surface emitting radiance Ke = 1 and reflecting ρ = 0.5;
// a one-sided box on its floor, [1.1, 2.6] × [0.9, 2.3], height 1 (edges off the bisection's
// dyadic lines, so elements straddle them). Every ray from an exposed point meets a front face,
// so B = πKe + ρB: B = πKe / (1 − ρ) = 2π.
SolveResult solveFurnaceWithABox() {
  Scene scene;
  Material m;
  m.name = "grey";
  m.diffuse = Rgb::all(0.5);
  m.emission = Rgb::all(1.0);
  scene.materials.push_back(m);
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0},
                                    {0, 0, 4}, {4, 0, 4}, {4, 4, 4}, {0, 4, 4}};
  std::vector<std::vector<int>> faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                         {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (auto& f : faces) std::reverse(f.begin() + 1, f.end());  // the room looks in
  addOpenBottomBox(p, faces, 1.1, 2.6, 0.9, 2.3, 1);
  scene.positions = p;
  for (const auto& f : faces) {
    ScenePolygon polygon;
    polygon.vertices = f;
    polygon.material = 0;
    scene.polygons.push_back(polygon);
  }
  SolveOptions options;
  options.targetElements = 400;
  options.raysPerElement = 4096;
  options.tolerance = 1e-7;
  options.threads = 2;
  return solveScene(scene, options);
}

TEST(BuriedParts, AFurnaceWithABoxOnItsFloorReachesEOverOneMinusRhoOnEveryExposedElement) {
  const SolveResult result = solveFurnaceWithABox();
  const Solution& s = result.solution;
  const PatchMesh& mesh = *s.mesh;
  const double exact = M_PI * 1.0 / (1 - 0.5);
  // The box's footprint, 2.1, of the room's 96 and the box's 7.9; within 0.3 (the cells along
  // its 5.8 of edge).
  EXPECT_NEAR(result.report.buriedAreaFraction, 2.1 / (96 + 7.9), 0.3 / (96 + 7.9));
  // Shooting spreads each element's power by its own row, so an element's B holds the noise of
  // the rays that landed on it: about 4096 (its area's share of all rays), 1.6% each bounce, so
  // σ ≈ 1.6% × ρ/(1 − ρ)^½ ≈ 1.2%. Elements straddling the box's edge add the cells it crosses,
  // counted whole on one side: rays from a hidden half counted as exposed are lost into the box,
  // at most about 8 cells of 64, half hidden: 6% of one row, which lowers B by that share at
  // most (ρ / (1 − ρ) = 1), about half of it on average.
  double sum = 0, area = 0, straddlingSum = 0, straddlingArea = 0;
  int straddling = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const double exposed = s.problem.area[e] / mesh.area(e);
    if (exposed < 0.1) continue;  // (almost) wholly under the box: nothing reaches it
    const double ratio = s.radiosity[e].g / exact;
    if (exposed < 0.9) {
      // Weighed by exposed area: a mostly hidden element's few cells carry a large relative
      // error in its area (4 cells of 64 against its exposed ones), but little power.
      ++straddling;
      straddlingSum += ratio * s.problem.area[e];
      straddlingArea += s.problem.area[e];
      if (exposed >= 0.5) {
        EXPECT_NEAR(ratio, 1.0, 4.0 / 64 / exposed + 4 * 0.012)
            << "element " << e << ", exposed " << exposed;
      }
    } else {
      EXPECT_NEAR(ratio, 1.0, 4.5 * 0.012) << "element " << e;
    }
    sum += s.radiosity[e].g * s.problem.area[e];
    area += s.problem.area[e];
  }
  // Without the exposed area, a straddling element half under the box would lose half its row
  // into the box and spread its light over its hidden half too: B about 30% low.
  ASSERT_GT(straddling, 4);
  EXPECT_NEAR(straddlingSum / straddlingArea, 1.0, 0.03 + 2 * 0.012 / std::sqrt(straddling));
  EXPECT_NEAR(sum / area / exact, 1.0, 0.005);
}

// Vertex colours and lightmaps weigh each element by its exposed area: the vertices along the
// box's footprint take their exposed elements' B, not a mean with the floor under the box (which
// nothing reaches: B = πKe there, half the exposed value). Every vertex of an element at least half
// exposed is within 6% of B; weighed by the whole areas, the footprint's vertices come out up to
// 13% low.
TEST(BuriedParts, VertexValuesWeighElementsByTheirExposedArea) {
  const SolveResult result = solveFurnaceWithABox();
  const Solution& s = result.solution;
  const PatchMesh& mesh = *s.mesh;
  const double exact = M_PI * 1.0 / (1 - 0.5);
  // A vertex value is a weighted mean of its elements: those mostly exposed are within 4.5σ
  // (5.4%); the straddling ones' few cells (≤ 6% of a row, half of it on average) weigh by their
  // smaller exposed area.
  constexpr double kVertexTolerance = 0.06;
  const VertexInterpolation byExposed(mesh, s.problem.area), byArea(mesh);
  const std::vector<Rgb> exposedValues = interpolateVertexRadiance(byExposed, s.radiosity);
  const std::vector<Rgb> areaValues = interpolateVertexRadiance(byArea, s.radiosity);
  double lowestByArea = 1;
  int checked = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (s.problem.area[e] < 0.5 * mesh.area(e)) continue;
    for (int corner : byExposed.triangle(e)) {
      // interpolateVertexRadiance gives L = B/π.
      EXPECT_NEAR(M_PI * exposedValues[corner].g / exact, 1.0, kVertexTolerance)
          << "element " << e << ", vertex " << corner;
      ++checked;
    }
    for (int corner : byArea.triangle(e))
      lowestByArea = std::min(lowestByArea, M_PI * areaValues[corner].g / exact);
  }
  EXPECT_GT(checked, 1000);
  EXPECT_LT(lowestByArea, 1 - kVertexTolerance);  // whole-area weights fail here
}

// The floor under the Cornell box's blocks is wholly buried (every one of its cells), and no light
// reaches it: every solver gives those elements their own emission alone (0), as the hierarchical
// solver and the path tracer do. A shooting solver spreads a shot by the rows of the shooter, and
// a few of its rays slip through the crack where a block meets the floor; landing on an element
// whose light is spread over its exposed area (at least 1/128 of it), each once lit a buried floor
// element brighter than the open floor (B_g 0.37-0.40 against 0.28, every seed).
TEST(BuriedParts, NoSolverLightsTheFloorWhollyUnderTheBlocks) {
  for (SolverKind solver : {SolverKind::Progressive, SolverKind::Southwell, SolverKind::GaussSeidel,
                            SolverKind::Jacobi}) {
    SolveOptions options;
    options.scenePath = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";
    options.solver = solver;
    options.seed = 5;
    options.threads = 2;
    const SolveResult result = runSolve(options);
    const Solution& s = result.solution;
    ASSERT_TRUE(s.exposure);
    int whollyBuried = 0;
    for (int e = 0; e < s.mesh->elementCount(); ++e) {
      if (s.exposure->buriedCells(e) != ~uint64_t(0)) continue;
      ++whollyBuried;
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(s.radiosity[e][c], s.problem.emission[e][c])
            << solverKindName(solver) << ", element " << e;
        if (!s.directIrradiance.empty()) {
          EXPECT_EQ(s.directIrradiance[e][c], 0.0) << solverKindName(solver) << ", element " << e;
        }
      }
    }
    EXPECT_GT(whollyBuried, 20) << solverKindName(solver);  // the two blocks' footprints
  }
}

}  // namespace
}  // namespace rad
