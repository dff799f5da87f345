// Textures in the solution and in the renders: a floor with a checker colour map of two known
// reflectances under a uniform sky. On an open upward plane the sky's first shot is exact
// (B = ρ π L, see test_direct_light), so each element's B is π L times its reflectance, which
// must be Kd × the area average of the texture over the element's UV footprint; and the
// interpolated radiosity view (--gather 0) must show the checker's own texels.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiosity/core/rng.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/direct_indirect_split.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/texture.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

// The two sRGB bytes of the checker and their linear values by IEC 61966-2-1, written out here.
constexpr unsigned char kDarkByte = 60, kLightByte = 200;
double linear(unsigned char byte) {
  const double c = byte / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
const double kKd = 0.9;   // the factor the texture multiplies
const double kSky = 2.0;  // sky radiance, W m^-2 sr^-1

// A 2×2 checker of 32×32-texel blocks as an uncompressed TGA (rows bottom first): light at the
// bottom left (u < 1/2, v < 1/2) and the top right, dark elsewhere. Blocks, not single texels, so
// the bilinear look-up the renders use is one colour more than half a texel from a border.
std::vector<unsigned char> checkerTga() {
  std::vector<unsigned char> out = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 64, 0, 64, 0, 24, 0};
  for (int y = 0; y < 64; ++y)  // bottom row first
    for (int x = 0; x < 64; ++x)
      for (int k = 0; k < 3; ++k) out.push_back((x < 32) == (y < 32) ? kLightByte : kDarkByte);
  return out;
}

// The texture's linear value at (u, v), from the layout above.
double checkerAt(double u, double v) {
  const bool left = std::fmod(u, 1.0) < 0.5, bottom = std::fmod(v, 1.0) < 0.5;
  return linear(left == bottom ? kLightByte : kDarkByte);
}

// The floor's texture coordinates: one period of the texture over the floor, shifted so the
// check borders (u or v = 1/2 and 1) fall off the lines along which the mesh bisects the square.
Eigen::Vector2d uvOf(const Eigen::Vector3d& p) {
  return {(p.x() + 1) / 2 + 0.13, (1 - p.z()) / 2 + 0.07};
}

// The floor y = 0 over [-1, 1]², facing up, under a uniform sky.
Scene checkerFloor() {
  Scene scene;
  scene.sourcePath = "checker-floor";
  const auto bytes = checkerTga();
  scene.textures.push_back(
      decodeTexture(bytes.data(), bytes.size(), "checker.tga", TextureEncoding::Srgb));
  Material m;
  m.name = "checker";
  m.diffuse = Rgb::all(kKd);
  m.diffuseTexture = 0;
  scene.materials.push_back(m);
  ScenePolygon floor;
  for (const Eigen::Vector3d& p :
       std::vector<Eigen::Vector3d>{{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}) {
    floor.vertices.push_back(static_cast<int>(scene.positions.size()));
    scene.positions.push_back(p);
    floor.uvs.push_back(uvOf(p));
  }
  scene.polygons.push_back(floor);
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = Rgb::all(kSky);
  sky.up = {0, 1, 0};
  scene.lights.push_back(sky);
  return scene;
}

SolveOptions quickOptions() {
  SolveOptions options;
  options.targetElements = 100;  // elements of about 0.2 × 0.2: many straddle the checks
  options.raysPerElement = 64;
  options.threads = 2;
  return options;
}

// An independent reference for the element's mean texel: the checker at the centroids of an
// n×n split of the element (each sub-triangle 1/n² of it), so off by at most the sub-triangles
// a check border crosses: 2 borders × about 2n of n² sub-triangles, 4/n of the contrast.
double meanTexelOver(const PatchMesh& mesh, int e, int n) {
  const auto c = mesh.corners(e);
  double sum = 0;
  int count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j)
      for (int flip = 0; flip < (i + j + 1 < n ? 2 : 1); ++flip) {
        const double a = (i + (flip ? 2.0 : 1.0) / 3) / n, b = (j + (flip ? 2.0 : 1.0) / 3) / n;
        const Eigen::Vector3d p = (1 - a - b) * c[0] + a * c[1] + b * c[2];
        const Eigen::Vector2d uv = uvOf(p);
        sum += checkerAt(uv.x(), uv.y());
        ++count;
      }
  return sum / count;
}

void expectSolutionFollowsTheTexture(const Solution& s) {
  const double dark = linear(kDarkByte), light = linear(kLightByte);
  const int n = s.mesh->elementCount();
  double sumB = 0, area = 0;
  int straddling = 0;
  constexpr int kGrid = 400;
  for (int e = 0; e < n; ++e) {
    const double b = s.radiosity[e].g;
    // Each element: π L Kd × its own mean texel (the straddlers a mix of the two).
    EXPECT_NEAR(b / (M_PI * kSky * kKd), meanTexelOver(*s.mesh, e, kGrid),
                4.0 / kGrid * (light - dark))
        << "element " << e;
    const double mix = b / (M_PI * kSky * kKd);
    if (mix > dark + 1e-3 && mix < light - 1e-3) ++straddling;
    sumB += b * s.mesh->area(e);
    area += s.mesh->area(e);
  }
  EXPECT_GT(straddling, 0);  // the mesh does not follow the checks: some elements mix them
  // The plane shows the checker's two halves equally: its mean is π L Kd × the mean texel. The
  // element averages are exact area integrals of the texels, so only the rounding of the
  // texture's float texels remains (relative 1e-7).
  const double expected = M_PI * kSky * kKd * 0.5 * (dark + light);
  EXPECT_NEAR(sumB / area, expected, 1e-6 * expected);
}

TEST(TexturedSolution, MeanRadiosityOverACheckerUnderTheSkyIsPiLTimesTheMeanLinearTexel) {
  const SolveResult result = solveScene(checkerFloor(), quickOptions());
  expectSolutionFollowsTheTexture(result.solution);
}

TEST(TexturedSolution, RefinedElementsAverageTheTextureOverTheirOwnFootprint) {
  SolveOptions options = quickOptions();
  options.formFactors = FormFactorMethod::Analytic;  // what refinement needs
  options.shadowRays = 1;
  options.refineThreshold = 0.05;  // the check borders show as jumps between elements
  options.refinePasses = 2;
  const SolveResult result = solveScene(checkerFloor(), options);
  ASSERT_GT(result.solution.mesh->elementCount(), result.report.elementsBeforeRefinement);
  expectSolutionFollowsTheTexture(result.solution);
}

TEST(TexturedRender, InterpolatedRadiosityViewShowsTheTexelsInsideElements) {
  const SolveResult result = solveScene(checkerFloor(), quickOptions());
  const Solution& s = result.solution;
  const RayCaster caster(*s.mesh);
  const RenderScene view(s.scene, *s.mesh, caster);
  const DirectIndirectSplit preview(view, s.radiosity, s.directIrradiance, 16);
  Rng rng(1);
  RayCounts counts;
  // Straight down onto points of the floor: on an open plane under the sky every point
  // reflects ρ(texel) L, whatever element it lies in, so each look-up shows its own check, also
  // inside the elements that straddle a border (0.05 from it, within one element).
  // Either side of the check borders (x = −0.26 and 0.74, z = 0.14 and −0.86) and between them.
  for (double x : {-0.31, -0.21, 0.3, 0.69, 0.79})
    for (double z : {0.19, 0.09, -0.4, -0.81, -0.91}) {
      const Rgb l = preview.radiance({x, 1, z}, {0, -1, 0}, rng, counts);
      const Eigen::Vector2d uv = uvOf({x, 0, z});
      // Far from a border the element's vertices agree and the value is exact; within an
      // element of a border the interpolated B/ρ mixes the two sides' (equal) incident light,
      // which is L π on both: exact too, up to rounding.
      const double expected = kKd * checkerAt(uv.x(), uv.y()) * kSky;
      EXPECT_NEAR(l.g, expected, 1e-6 * expected) << "at x " << x << ", z " << z;
    }
}

}  // namespace
}  // namespace rad
