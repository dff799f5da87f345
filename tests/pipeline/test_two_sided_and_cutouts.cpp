// Two-sided surfaces and alpha cut-outs in the radiosity solve, against answers that need no
// simulation: a lone plane under a uniform sky sees all of it from its upper side (B = ρπL, with
// every sky ray unoccluded, so exact up to rounding) and none from its lower side; a two-sided
// wall between two rooms keeps each room's light on its own side (exactly zero on the other);
// a checker-masked quad over a floor in a vertical sun lets through exactly the light of its
// transparent checks where the floor's receiver points lie under them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "radiosity/formfactors/receiver_points.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene.h"
#include "radiosity/scene/two_sided.h"

namespace rad {
namespace {

const Rgb kRho{0.5, 0.4, 0.3};

int addMaterial(Scene& scene, const std::string& name, const Rgb& rho) {
  Material m;
  m.name = name;
  m.diffuse = rho;
  scene.materials.push_back(m);
  return static_cast<int>(scene.materials.size()) - 1;
}

// A quad with corners counter-clockwise seen from the front, and texture coordinates `uvs`.
void addQuad(Scene& scene, const std::vector<Eigen::Vector3d>& corners, int material,
             const std::vector<Eigen::Vector2d>& uvs = {}) {
  ScenePolygon polygon;
  for (const auto& c : corners) {
    polygon.vertices.push_back(static_cast<int>(scene.positions.size()));
    scene.positions.push_back(c);
  }
  polygon.material = material;
  polygon.uvs = uvs;
  scene.polygons.push_back(polygon);
}

SolveOptions quickOptions(int elements = 128) {
  SolveOptions options;
  options.targetElements = elements;
  options.raysPerElement = 64;
  options.threads = 2;
  return options;
}

Light sky(const Rgb& radiance) {
  Light light;
  light.type = LightType::Sky;
  light.radiance = radiance;
  return light;
}

Light pointLight(const Eigen::Vector3d& position, const Rgb& intensity) {
  Light light;
  light.type = LightType::Point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

// A quad at y = 0 over [-1, 1]² facing down, under a uniform sky (the upper hemisphere).
Scene skyOverDownwardQuad(bool twoSided) {
  Scene scene;
  scene.sourcePath = "test";
  scene.lights = {sky({1, 2, 3})};
  addMaterial(scene, "grey", kRho);
  addQuad(scene, {{-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}}, 0);  // normal -y
  applyTwoSidedInput(scene, {twoSided, {}});
  addBackSides(scene);
  return scene;
}

TEST(TwoSidedSolve, OneSidedQuadFacingDownGetsNoSkyAndHasNoUpperSide) {
  const SolveResult result = solveScene(skyOverDownwardQuad(false), quickOptions());
  const PatchMesh& mesh = *result.solution.mesh;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    EXPECT_LT(mesh.normal(e).y(), 0) << "an element facing up: the upper side exists";
    EXPECT_EQ(result.solution.radiosity[e].maxComponent(), 0.0) << "element " << e;
  }
}

TEST(TwoSidedSolve, TwoSidedQuadFacingDownIsLitOnItsUpperSideOnly) {
  const SolveResult result = solveScene(skyOverDownwardQuad(true), quickOptions());
  const PatchMesh& mesh = *result.solution.mesh;
  const Rgb radiance = result.solution.scene.lights[0].radiance;
  int up = 0, down = 0;
  double upArea = 0, downArea = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const Rgb& b = result.solution.radiosity[e];
    if (mesh.normal(e).y() > 0) {
      // Every sky ray from the upper side is above the horizon and leaves the scene (its own
      // lower side, coincident, faces away), and nothing else is there to reflect: exact.
      ++up;
      upArea += mesh.area(e);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(b[c], kRho[c] * M_PI * radiance[c], 1e-12 * radiance[c]) << "element " << e;
    } else {
      ++down;
      downArea += mesh.area(e);
      EXPECT_EQ(b.maxComponent(), 0.0) << "element " << e;
    }
  }
  EXPECT_GT(up, 0);
  EXPECT_GT(down, 0);
  EXPECT_NEAR(upArea, 4.0, 1e-12);  // each side covers the whole quad
  EXPECT_NEAR(downArea, 4.0, 1e-12);
}

// The least of I cosθ / r² over the element: on a plane, a point light's irradiance I h / r³ falls
// with the distance r from the light, which over a triangle is greatest at a corner. A lower
// bound of the element's mean E_d however the solver samples it.
double pointLightLeast(const Light& light, const std::array<Eigen::Vector3d, 3>& corners,
                       const Eigen::Vector3d& n, int channel) {
  double least = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& x : corners) {
    const Eigen::Vector3d d = light.position - x;
    least = std::min(
        least, light.intensity[channel] * std::max(0.0, n.dot(d.normalized())) / d.squaredNorm());
  }
  return least;
}

TEST(TwoSidedSolve, AWallBetweenTwoRoomsShowsEachSideOnlyItsOwnRoom) {
  // A two-sided wall x = 0 between a room lit red (x < 0) and one lit blue (x > 0), each with a
  // floor that reflects its light onto the wall. The wall reaches below the floors and above
  // every line from a light to the other room, so no light path crosses from room to room:
  // the red side has no blue at all and the blue side no red, however the rays fall.
  Scene scene;
  scene.sourcePath = "test";
  const int grey = addMaterial(scene, "grey", Rgb::all(0.5));
  const int wall = addMaterial(scene, "wall", Rgb::all(0.5));
  addQuad(scene, {{0, -1, -2}, {0, -1, 2}, {0, 2, 2}, {0, 2, -2}}, wall);  // faces -x (red room)
  addQuad(scene, {{-2, 0, -1}, {-2, 0, 1}, {0, 0, 1}, {0, 0, -1}}, grey);  // red room's floor
  addQuad(scene, {{0, 0, -1}, {0, 0, 1}, {2, 0, 1}, {2, 0, -1}}, grey);    // blue room's floor
  const Light red = pointLight({-1, 1, 0}, {1, 0, 0});
  const Light blue = pointLight({1, 1, 0}, {0, 0, 1});
  scene.lights = {red, blue};
  applyTwoSidedInput(scene, {false, {"wall"}});
  ASSERT_EQ(addBackSides(scene), 1);

  const SolveResult result = solveScene(scene, quickOptions(600));
  const PatchMesh& mesh = *result.solution.mesh;
  int redSide = 0, blueSide = 0;
  double redFromFloor = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.material(e) != wall) continue;
    const Rgb& b = result.solution.radiosity[e];
    const Eigen::Vector3d n = mesh.normal(e);
    const bool facesRed = n.x() < 0;
    (facesRed ? redSide : blueSide)++;
    EXPECT_EQ(facesRed ? b.b : b.r, 0.0) << "light crossed the wall at element " << e;
    // Above the floors: at least the direct light of its own room (the floor adds to it).
    const auto corners = mesh.corners(e);
    if (std::min({corners[0].y(), corners[1].y(), corners[2].y()}) < 0) continue;
    const Light& own = facesRed ? red : blue;
    const int c = facesRed ? 0 : 2;
    const double direct = 0.5 * pointLightLeast(own, mesh.corners(e), n, c);
    EXPECT_GE(b[c], direct * (1 - 1e-9)) << "element " << e;
    if (facesRed) redFromFloor += (b[c] - direct) * mesh.area(e);
  }
  EXPECT_GT(redSide, 0);
  EXPECT_GT(blueSide, 0);
  EXPECT_GT(redFromFloor, 0) << "the red floor's light did not reach its side of the wall";
}

// An 8 × 8 checker of coverage 0 and 1 (colour white), texel (x, y) counted from the top row
// as image files store them: transparent where x + y is even.
Texture checkerMask() {
  Texture t;
  t.source = "checker";
  t.width = t.height = 8;
  t.rgba.assign(8 * 8 * 4, 1.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) t.rgba[4 * (8 * y + x) + 3] = (x + y) % 2 == 0 ? 0.0f : 1.0f;
  return t;
}

// Whether the checker is transparent at (u, v) in [0, 1)²: v counts up from the bottom row.
bool transparentAt(double u, double v) {
  const int x = static_cast<int>(std::floor(u * 8)), yFromTop = 7 - static_cast<int>(v * 8);
  return (x + yFromTop) % 2 == 0;
}

TEST(CutoutSolve, AMaskedQuadLetsThroughTheLightOfItsTransparentChecks) {
  // Sun straight down (no angular size) onto a floor y = 0 over [-1, 1]², under a quad y = 1 of
  // the same extent masked by the checker (u = (x+1)/2, v = (z+1)/2): a floor point is lit
  // exactly when the texel above it is transparent. The thresholded bilinear coverage of a
  // checker is the checker itself (the 0.5 level set of the bilinear blend of 0/1 checks runs
  // along the texel edges), so each floor element's first shot is ρ E × (its receiver points
  // under transparent checks) / 3, and nothing else reaches the floor (the mask's underside is
  // its black back).
  Scene scene;
  scene.sourcePath = "test";
  scene.textures.push_back(checkerMask());
  const int floor = addMaterial(scene, "floor", kRho);
  const int mask = addMaterial(scene, "mask", Rgb::all(0.5));
  scene.materials[mask].alphaTexture = 0;
  const std::vector<Eigen::Vector2d> uvs{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  addQuad(scene, {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, floor, uvs);
  addQuad(scene, {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}, mask, uvs);
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = Rgb::all(1);
  sun.angularDiameterDegrees = 0;
  scene.lights = {sun};

  SolveOptions options = quickOptions();
  options.maxArea = 0.02;  // floor elements within one check each (checks are 0.25 wide)
  const SolveResult result = solveScene(scene, options);
  const PatchMesh& mesh = *result.solution.mesh;
  double floorArea = 0, litArea = 0, straddlingArea = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    if (mesh.material(e) != floor) continue;
    int lit = 0;
    for (const auto& x : receiverPoints(mesh.corners(e)))
      lit += transparentAt((x.x() + 1) / 2, (x.z() + 1) / 2);
    const Rgb& b = result.solution.radiosity[e];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(b[c], kRho[c] * lit / 3.0, 1e-12) << "floor element " << e;
    // An element whose centroid and corners are not all in one check straddles a check edge.
    const Eigen::Vector3d m = mesh.centroid(e);
    const bool inside = transparentAt((m.x() + 1) / 2, (m.z() + 1) / 2);
    bool straddles = false;
    for (const auto& x : receiverPoints(mesh.corners(e)))
      straddles |= transparentAt((x.x() + 1) / 2, (x.z() + 1) / 2) != inside;
    floorArea += mesh.area(e);
    litArea += mesh.area(e) * lit / 3.0;
    straddlingArea += straddles ? mesh.area(e) : 0;
  }
  ASSERT_NEAR(floorArea, 4.0, 1e-12);
  // The floor's irradiance over the open sun's: the transparent fraction 1/2 of the checker, up
  // to the elements that straddle a check edge (each off by at most its whole area).
  EXPECT_NEAR(litArea / floorArea, 0.5, straddlingArea / floorArea + 1e-12);
}

TEST(CutoutSolve, ACutoutReflectsByItsAverageCoverage) {
  // A masked quad alone under a vertical sun: each element reflects ρ E × its covered fraction
  // (nothing else reaches it), 0 or 1 for an element inside one check; over the whole quad the
  // checker covers half, so the reflected power is ρ E × 4 × 1/2 up to the elements that
  // straddle a check edge.
  Scene scene;
  scene.sourcePath = "test";
  scene.textures.push_back(checkerMask());
  const int mask = addMaterial(scene, "mask", kRho);
  scene.materials[mask].alphaTexture = 0;
  addQuad(scene, {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}}, mask,
          {{0, 0}, {0, 1}, {1, 1}, {1, 0}});
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = Rgb::all(1);
  sun.angularDiameterDegrees = 0;
  scene.lights = {sun};
  SolveOptions options = quickOptions();
  options.maxArea = 0.02;
  const SolveResult result = solveScene(scene, options);
  const PatchMesh& mesh = *result.solution.mesh;
  double power = 0, straddlingArea = 0;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const double b = result.solution.radiosity[e].r;
    power += b * mesh.area(e);
    const auto c = mesh.corners(e);
    const Eigen::Vector3d m = mesh.centroid(e);
    const bool open = transparentAt((m.x() + 1) / 2, (m.z() + 1) / 2);
    bool straddles = false;
    for (int k = 0; k < 3; ++k) {  // points just inside each corner
      const Eigen::Vector3d x = 0.9 * c[k] + 0.1 * m;
      straddles |= transparentAt((x.x() + 1) / 2, (x.z() + 1) / 2) != open;
    }
    if (straddles)
      straddlingArea += mesh.area(e);
    else
      EXPECT_NEAR(b, open ? 0.0 : kRho.r, 1e-12) << "element " << e;
  }
  EXPECT_NEAR(power, kRho.r * 2.0, kRho.r * straddlingArea + 1e-9);
}

}  // namespace
}  // namespace rad
