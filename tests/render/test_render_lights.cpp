// Point, spot, directional, sky and environment lights in the camera renders
// (render/scene_lights.h) against analytic answers. On surfaces that see no other surface the
// radiance is ρ/π times the lights' irradiance: ρ I cosθ / (π r²) under a point light, ρ E cosθ / π
// under a sun (hard, or a disc wholly above the surface's horizon: ∫ L cos dω over the disc is E
// cosθ by symmetry), ρ L on an open upward plane under a uniform sky and ρ L / 2 on a lone vertical
// one. Delta lights are sampled exactly, so there the methods must agree to rounding; where they
// sample (the sun's disc, the sky) each ray's estimate is averaged over n samples and must lie
// within 5σ of the answer, σ the standard error from the samples' own spread. Every method is held
// to each answer, and on a lit box whose interreflection has no closed form, the unbiased methods
// to each other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/core/rng.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/bdpt.h"
#include "radiosity/render/direct_indirect_split.h"
#include "radiosity/render/direct_lighting.h"
#include "radiosity/render/distribution_ray_tracer.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/interpolated_preview.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/render/whitted_ray_tracer.h"
#include "radiosity/scene/light_shapes.h"
#include "tests/support/clear_sky_reference.h"
#include "tests/support/test_scenes.h"

namespace rad {
namespace {

const Rgb kRho{0.5, 0.4, 0.3};

Scene sceneWith(const std::vector<Light>& lights) { return testing::greyScene(kRho, lights); }

void addQuad(Scene& scene, const std::vector<Eigen::Vector3d>& corners, int material = 0) {
  testing::addPolygon(scene, corners, material);
}

// The floor y = 0 over [-1, 1]², facing up.
Scene floorScene(const std::vector<Light>& lights) {
  Scene scene = sceneWith(lights);
  addQuad(scene, {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}});
  return scene;
}

// A plane through the origin tilted 40° about x: normal (0, cos 40°, sin 40°).
const double kTilt = 40 * M_PI / 180;
Scene tiltedScene(const std::vector<Light>& lights) {
  Scene scene = sceneWith(lights);
  const Eigen::Vector3d u(1, 0, 0), v(0, std::sin(kTilt), -std::cos(kTilt));
  addQuad(scene, {-u - v, u - v, u + v, -u + v});
  return scene;
}

Light pointLight(const Eigen::Vector3d& position, const Rgb& intensity) {
  Light light;
  light.type = LightType::Point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

Light sun(const Rgb& irradiance, double diameterDegrees) {
  Light light;
  light.type = LightType::Directional;
  light.direction = {0, -1, 0};
  light.irradiance = irradiance;
  light.angularDiameterDegrees = diameterDegrees;
  return light;
}

Light sky(const Rgb& radiance) {
  Light light;
  light.type = LightType::Sky;
  light.radiance = radiance;
  return light;
}

// A scene solved (the final gather reads the solution) and viewed by every method.
struct World {
  SolveResult solved;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
  Camera camera;
};

std::unique_ptr<World> solveWorld(const Scene& scene, const Eigen::Vector3d& eye,
                                  int elements = 128) {
  auto w = std::make_unique<World>();
  SolveOptions options;
  options.targetElements = elements;
  options.raysPerElement = 256;
  options.threads = 2;
  w->solved = solveScene(scene, options);
  w->caster = std::make_unique<RayCaster>(*w->solved.solution.mesh);
  w->view =
      std::make_unique<RenderScene>(w->solved.solution.scene, *w->solved.solution.mesh, *w->caster);
  w->camera.position = eye;
  w->camera.lookAt = {0, 0, 0};
  w->camera.vfovDegrees = 60;
  w->camera.width = w->camera.height = 16;
  return w;
}

using Methods = std::vector<std::pair<std::string, std::unique_ptr<Integrator>>>;

// Every method that renders these lights; `local`: with the local model `direct`, which ignores
// shadows (right where nothing shadows).
Methods allMethods(const World& w, bool local = true) {
  Methods m;
  m.emplace_back("path", std::make_unique<PathTracer>(*w.view));
  m.emplace_back("bdpt", std::make_unique<Bdpt>(*w.view, w.camera));
  m.emplace_back("radiosity gather 4",
                 std::make_unique<FinalGather>(*w.view, w.solved.solution.radiosity,
                                               FinalGatherOptions{4, 2}));
  m.emplace_back("whitted", std::make_unique<WhittedRayTracer>(*w.view));
  m.emplace_back("distribution", std::make_unique<DistributionRayTracer>(*w.view));
  if (local) m.emplace_back("direct", std::make_unique<DirectLighting>(*w.view));
  return m;
}

struct Estimate {
  Rgb mean, sigma;  // sigma: the standard error of the mean
};

Estimate estimate(const Integrator& integrator, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& target, int n, uint64_t seed) {
  const Eigen::Vector3d d = (target - origin).normalized();
  Rng rng(seed);
  RayCounts counts;
  Rgb sum, sumSquares;
  for (int k = 0; k < n; ++k) {
    const Rgb v = integrator.radiance(origin, d, rng, counts);
    sum += v;
    sumSquares += v * v;
  }
  Estimate e;
  e.mean = sum / n;
  for (int c = 0; c < 3; ++c)
    e.sigma[c] = std::sqrt(std::max(0.0, sumSquares[c] / n - e.mean[c] * e.mean[c]) / (n - 1));
  return e;
}

// Within 5σ, plus 1e-6 relative: the ray's hit is found in single precision (Embree), so it lies
// some 1e-7 of the scene's size from the aimed-at point, and the light there differs as much.
void expectRadiance(const Estimate& got, const Rgb& want, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got.mean[c], want[c], 5 * got.sigma[c] + 1e-6 * std::abs(want[c]) + 1e-12)
        << what << " channel " << c << " (σ " << got.sigma[c] << ")";
}

// Points of the square [-0.8, 0.8]² on a plane spanned by unit u and v.
std::vector<Eigen::Vector3d> grid(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) points.push_back((-0.8 + i * 0.53) * u + (-0.7 + j * 0.5) * v);
  return points;
}

TEST(RenderLights, PointLightOverAPlaneIsRhoICosOverPiRSquaredInEveryMethod) {
  const Light light = pointLight({0.3, 0.8, -0.2}, {10, 20, 30});
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({light}), eye);
  for (const auto& [name, method] : allMethods(*w))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1})) {
      const Eigen::Vector3d d = light.position - x;
      const Rgb want = kRho * light.intensity * (d.normalized().y() / (M_PI * d.squaredNorm()));
      expectRadiance(estimate(*method, eye, x, 4, 1), want, name);
    }
}

TEST(RenderLights, SpotIsZeroOutsideItsOuterConeAndThePointValueInsideItsInnerCone) {
  Light spot = pointLight({0, 1, 0}, {5, 6, 7});
  spot.type = LightType::Spot;
  spot.direction = {0, -1, 0};
  spot.cosOuter = std::cos(30 * M_PI / 180);  // the floor's circle of radius tan 30° ≈ 0.577
  spot.cosInner = std::cos(20 * M_PI / 180);  // radius tan 20° ≈ 0.364
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({spot}), eye);
  for (const auto& [name, method] : allMethods(*w)) {
    for (const double r : {0.0, 0.2, 0.33}) {
      const Eigen::Vector3d x(r, 0, 0.05), d = spot.position - x;
      const Rgb want = kRho * spot.intensity * (d.normalized().y() / (M_PI * d.squaredNorm()));
      expectRadiance(estimate(*method, eye, x, 4, 2), want, name + " inside");
    }
    for (const double r : {0.62, 0.8})
      expectRadiance(estimate(*method, eye, {r, 0, 0.05}, 4, 3), {}, name + " outside");
  }
}

TEST(RenderLights, DirectionalLightOnATiltedPlaneIsRhoECosThetaOverPi) {
  const Rgb e{100, 200, 300};
  const Eigen::Vector3d eye(0, 2, 2.5);
  const Eigen::Vector3d u(1, 0, 0), v(0, std::sin(kTilt), -std::cos(kTilt));
  const Rgb want = kRho * e * (std::cos(kTilt) / M_PI);
  // Hard, the real sun's 0.53°, and a disc of half-angle 44.5° (just inside the plane's horizon,
  // 50° from the normal), which bounce rays reach often: there MIS carries real weight.
  for (const double diameter : {0.0, 0.53, 89.0}) {
    const auto w = solveWorld(tiltedScene({sun(e, diameter)}), eye);
    // The local model `direct` takes the sun at its disc's centre: exact for the hard sun only.
    for (const auto& [name, method] : allMethods(*w, diameter == 0))
      for (const Eigen::Vector3d& x : grid(u, v))
        expectRadiance(estimate(*method, eye, x, 64, 4), want,
                       name + " diameter " + std::to_string(diameter));
  }
}

TEST(RenderLights, UniformSkyOnAnOpenUpwardPlaneIsRhoL) {
  const Light light = sky({1, 2, 3});
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({light}), eye);
  for (const auto& [name, method] : allMethods(*w))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1}))
      expectRadiance(estimate(*method, eye, x, 16, 5), kRho * light.radiance, name);
}

// Facing +z: half its hemisphere is the black ground below the horizon.
TEST(RenderLights, UniformSkyOnALoneVerticalQuadIsHalfRhoL) {
  const Light light = sky({1, 2, 3});
  Scene scene = sceneWith({light});
  addQuad(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  const Eigen::Vector3d eye(0.3, 0.2, 3);
  const auto w = solveWorld(scene, eye);
  for (const auto& [name, method] : allMethods(*w))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 1, 0}))
      expectRadiance(estimate(*method, eye, x, 256, 6), 0.5 * kRho * light.radiance, name);
}

// CIE overcast, L(θ) = L_z (1 + 2 cos θ)/3: E = 7πL_z/9 facing up, L_z (π/6 + 4/9) on a vertical
// plane (light_shapes.h), so radiance ρE/π.
TEST(RenderLights, CieOvercastSkyOnAnUpwardAndAVerticalPlane) {
  Light light = sky({1, 2, 3});
  light.skyModel = SkyModel::CieOvercast;
  {
    const Eigen::Vector3d eye(0, 2.5, 1.5);
    const auto w = solveWorld(floorScene({light}), eye);
    for (const auto& [name, method] : allMethods(*w))
      for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1}))
        expectRadiance(estimate(*method, eye, x, 64, 8), kRho * light.radiance * (7.0 / 9),
                       name + " upward");
  }
  Scene scene = sceneWith({light});
  addQuad(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  const Eigen::Vector3d eye(0.3, 0.2, 3);
  const auto w = solveWorld(scene, eye);
  for (const auto& [name, method] : allMethods(*w))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 1, 0}))
      expectRadiance(estimate(*method, eye, x, 256, 9),
                     kRho * light.radiance * ((M_PI / 6 + 4.0 / 9) / M_PI), name + " vertical");
}

TEST(RenderLights, RaysThatLeaveTheSceneSeeTheSkyAboveTheHorizonAndTheSunsDisc) {
  const Light theSky = sky({1, 2, 3});
  const Light theSun = sun({1000, 1000, 1000}, 10);
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({theSky, theSun}), eye);
  const Rgb disc = sunRadiance(theSun);
  ASSERT_GT(disc.r, 1000);  // E / (π sin² 5°)
  for (const auto& [name, method] : allMethods(*w)) {
    const auto& integrator = *method;  // a lambda may not capture a structured binding (C++17)
    const auto seen = [&](const Eigen::Vector3d& d) {
      return estimate(integrator, eye, eye + d, 2, 7);
    };
    expectRadiance(seen({0.05, 1, 0}), theSky.radiance + disc, name + " into the sun");
    expectRadiance(seen({1, 1, 0}), theSky.radiance, name + " the sky");
    expectRadiance(seen({1, -0.2, 0}), {}, name + " below the horizon");
  }
}

// Environment lights and the CIE clear sky, sampled by their map (scene/environment_map.h). The
// local model `direct` integrates the map's irradiance table instead, held to the table's stated
// accuracy (1% for these smooth maps and a texel seen from its table node).
void expectDirectWithin(const Integrator& direct, const Eigen::Vector3d& eye,
                        const Eigen::Vector3d& x, const Rgb& want, double relative) {
  const Estimate e = estimate(direct, eye, x, 1, 12);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(e.mean[c], want[c], relative * want[c]) << "direct channel " << c;
}

// A constant environment L: ρL on an open upward plane and on a lone vertical one (half sky, half
// ground, both L), where the uniform sky gives ρL/2 on the vertical one.
TEST(RenderLights, ConstantEnvironmentIsRhoLOnAnUpwardAndAVerticalPlane) {
  const Light light = environmentLight(16, 8, std::vector<Rgb>(128, Rgb(1, 2, 3)));
  const Rgb want = kRho * Rgb(1, 2, 3);
  {
    const Eigen::Vector3d eye(0, 2.5, 1.5);
    const auto w = solveWorld(floorScene({light}), eye);
    for (const auto& [name, method] : allMethods(*w, false))
      for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1}))
        expectRadiance(estimate(*method, eye, x, 16, 20), want, name + " upward");
    expectDirectWithin(DirectLighting(*w->view), eye, {0.2, 0, 0.1}, want, 0.01);
  }
  Scene scene = sceneWith({light});
  addQuad(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  const Eigen::Vector3d eye(0.3, 0.2, 3);
  const auto w = solveWorld(scene, eye);
  for (const auto& [name, method] : allMethods(*w, false))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 1, 0}))
      expectRadiance(estimate(*method, eye, x, 16, 21), want, name + " vertical");
  expectDirectWithin(DirectLighting(*w->view), eye, {0.2, 0.1, 0}, want, 0.01);
}

// An image bright (L) above the horizon and black below renders as the uniform sky: ρL facing up,
// ρL/2 on a lone vertical plane, every method within the same 5σ.
TEST(RenderLights, EnvironmentBrightOnlyAboveTheHorizonIsTheUniformSky) {
  std::vector<Rgb> texels(16 * 8);
  std::fill(texels.begin(), texels.begin() + 16 * 4, Rgb(1, 2, 3));
  const Light light = environmentLight(16, 8, texels);
  {
    const Eigen::Vector3d eye(0, 2.5, 1.5);
    const auto w = solveWorld(floorScene({light}), eye);
    for (const auto& [name, method] : allMethods(*w, false))
      for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1}))
        expectRadiance(estimate(*method, eye, x, 16, 22), kRho * Rgb(1, 2, 3), name + " upward");
  }
  Scene scene = sceneWith({light});
  addQuad(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
  const Eigen::Vector3d eye(0.3, 0.2, 3);
  const auto w = solveWorld(scene, eye);
  for (const auto& [name, method] : allMethods(*w, false))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 1, 0}))
      expectRadiance(estimate(*method, eye, x, 256, 23), 0.5 * kRho * Rgb(1, 2, 3),
                     name + " vertical");
}

// One bright texel (a sun in an HDRI) in an otherwise black map: an upward plane receives
// E = L ∫ cosθ dω over the texel = L (2π/W)(sin²θ₁ − sin²θ₀)/2, θ₀, θ₁ its row's edges. The light
// sample lands in the texel every time and is worth ρ L Ω cosθ/π, Ω the texel's solid angle:
// its values span ρ L Ω (cosθ₀ − cosθ₁)/π, so 16 samples per pixel have a standard error of at
// most half that over 4 (cosine-weighted sampling alone would find the texel once in ~150).
TEST(RenderLights, OneBrightTexelIsFoundByImportanceSamplingWithLowVariance) {
  const int width = 32, height = 16, row = 3, column = 5;
  std::vector<Rgb> texels(width * height);
  texels[row * width + column] = Rgb(1000, 2000, 3000);
  const Light light = environmentLight(width, height, texels);
  const double s0 = std::sin(M_PI * row / height), s1 = std::sin(M_PI * (row + 1) / height);
  const double cosIntegral = 2 * M_PI / width * (s1 * s1 - s0 * s0) / 2;
  const Rgb want = kRho * Rgb(1000, 2000, 3000) * (cosIntegral / M_PI);
  const double omega =
      2 * M_PI / width * (std::cos(M_PI * row / height) - std::cos(M_PI * (row + 1) / height));
  const double spread = kRho.r * 1000 * omega *
                        (std::cos(M_PI * row / height) - std::cos(M_PI * (row + 1) / height)) /
                        M_PI;
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({light}), eye);
  for (const auto& [name, method] : allMethods(*w, false))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1})) {
      const Estimate e = estimate(*method, eye, x, 16, 24);
      expectRadiance(e, want, name);
      EXPECT_LT(e.sigma.r, spread / 2 / 4) << name;
    }
  expectDirectWithin(DirectLighting(*w->view), eye, {0.2, 0, 0.1}, want, 0.01);
}

// The CIE clear sky, the sun 35° high: ρE/π on an open upward plane, E integrated numerically
// from the formula (tests/support/clear_sky_reference.h).
TEST(RenderLights, CieClearSkyOnAnOpenUpwardPlaneMatchesTheIntegratedFormula) {
  const double e = 35 * M_PI / 180;
  const Light light = cieClearSky({1, 2, 3}, {std::cos(e) * 0.6, -std::sin(e), std::cos(e) * 0.8});
  const Rgb want = kRho * light.radiance * (testing::clearSkyUpwardIrradiance(35) / M_PI);
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({light}), eye);
  for (const auto& [name, method] : allMethods(*w, false))
    for (const Eigen::Vector3d& x : grid({1, 0, 0}, {0, 0, 1}))
      expectRadiance(estimate(*method, eye, x, 64, 25), want, name);
  expectDirectWithin(DirectLighting(*w->view), eye, {0.2, 0, 0.1}, want, 0.01);
}

// Rays that leave the scene see the environment all round: the image's top row above the
// horizon, its bottom row below (no black ground), camera rays included.
TEST(RenderLights, RaysThatLeaveTheSceneSeeTheEnvironmentAllRound) {
  const Light light = environmentLight(
      2, 2, {Rgb(1, 1, 1), Rgb(1, 1, 1), Rgb(0.25, 0.5, 0.75), Rgb(0.25, 0.5, 0.75)});
  const Eigen::Vector3d eye(0, 2.5, 1.5);
  const auto w = solveWorld(floorScene({light}), eye);
  for (const auto& [name, method] : allMethods(*w)) {
    const auto& integrator = *method;  // a lambda may not capture a structured binding (C++17)
    const auto seen = [&](const Eigen::Vector3d& d) {
      return estimate(integrator, eye, eye + d, 2, 26);
    };
    expectRadiance(seen({1, 1, 0}), Rgb(1, 1, 1), name + " above");
    expectRadiance(seen({1, -0.2, 0}), Rgb(0.25, 0.5, 0.75), name + " below the horizon");
  }
}

// An open box (a floor and four walls facing in, no lid) under a sky, a sun low enough for the
// walls to shadow part of the floor, and a point light inside: interreflection with no closed
// form. Path tracing and bdpt are both unbiased: their means over a set of pixels agree within
// the noise. The final gather reads the solution's piecewise-constant elements along its gather
// rays, a discretisation bias bounded by a stated 2% of the light, and the interpolated solution
// (--gather 0) shows that bias whole at the first hit: 5%. (Measured: the four means agree within
// 0.3%.)
TEST(RenderLights, PathTracerBdptAndFinalGatherAgreeOnALitBox) {
  Light theSun = sun({3, 3, 3}, 2);
  theSun.direction = Eigen::Vector3d(0.6, -1, 0.3).normalized();
  Scene scene = sceneWith({sky({0.5, 0.5, 0.5}), theSun, pointLight({0.2, 0.5, 0.1}, {1, 1, 1})});
  addQuad(scene, {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}});    // floor, up
  addQuad(scene, {{-1, 0, -1}, {1, 0, -1}, {1, 1, -1}, {-1, 1, -1}});  // back, +z
  addQuad(scene, {{-1, 0, 1}, {-1, 1, 1}, {1, 1, 1}, {1, 0, 1}});      // front, −z
  addQuad(scene, {{-1, 0, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, 0, 1}});  // left, +x
  addQuad(scene, {{1, 0, -1}, {1, 0, 1}, {1, 1, 1}, {1, 1, -1}});      // right, −x
  const Eigen::Vector3d eye(0, 2.5, 0.4);
  const auto w = solveWorld(scene, eye, 600);
  std::vector<Eigen::Vector3d> targets;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      targets.push_back({-0.95 + i * 0.38, 0.3 * (i % 2), -0.95 + j * 0.38});
  const auto meanOver = [&](const Integrator& method, int n) {
    Estimate total;
    for (size_t k = 0; k < targets.size(); ++k) {
      const Estimate e = estimate(method, eye, targets[k], n, 100 + k);
      total.mean += e.mean;
      total.sigma += e.sigma * e.sigma;
    }
    total.mean = total.mean / double(targets.size());
    for (int c = 0; c < 3; ++c) total.sigma[c] = std::sqrt(total.sigma[c]) / targets.size();
    return total;
  };
  const Estimate path = meanOver(PathTracer(*w->view), 1024);
  const Estimate bdpt = meanOver(Bdpt(*w->view, w->camera), 1024);
  const Estimate gather =
      meanOver(FinalGather(*w->view, w->solved.solution.radiosity, FinalGatherOptions{16}), 64);
  const Estimate preview = meanOver(InterpolatedPreview(*w->view, w->solved.solution.radiosity), 2);
  // The direct light at the hit, the solution's indirect part interpolated: the sun, sky and lamp
  // each counted once (their mean share taken out of the solution's B).
  const Estimate hybrid = meanOver(DirectIndirectSplit(*w->view, w->solved.solution.radiosity,
                                                       w->solved.solution.directIrradiance, 4),
                                   64);
  for (int c = 0; c < 3; ++c) {
    const double noise = std::hypot(path.sigma[c], bdpt.sigma[c]);
    ASSERT_GT(noise, 0);
    EXPECT_NEAR(bdpt.mean[c], path.mean[c], 5 * noise) << "channel " << c;
    // MIS keeps the sun's small disc from making heavy tails: the means are tight.
    EXPECT_LT(path.sigma[c], 0.01 * path.mean[c]) << "channel " << c;
    EXPECT_LT(bdpt.sigma[c], 0.01 * bdpt.mean[c]) << "channel " << c;
    EXPECT_NEAR(gather.mean[c], path.mean[c],
                5 * std::hypot(path.sigma[c], gather.sigma[c]) + 0.02 * path.mean[c])
        << "channel " << c;
    EXPECT_NEAR(preview.mean[c], gather.mean[c], 5 * gather.sigma[c] + 0.05 * gather.mean[c])
        << "channel " << c;
    EXPECT_NEAR(hybrid.mean[c], path.mean[c],
                5 * std::hypot(path.sigma[c], hybrid.sigma[c]) + 0.02 * path.mean[c])
        << "channel " << c;
  }
  std::printf(
      "lit box mean (r): path %.5f ± %.5f, bdpt %.5f ± %.5f, gather %.5f ± %.5f, "
      "gather 0 %.5f, gather 0 light rays 4 %.5f ± %.5f\n",
      path.mean.r, path.sigma.r, bdpt.mean.r, bdpt.sigma.r, gather.mean.r, gather.sigma.r,
      preview.mean.r, hybrid.mean.r, hybrid.sigma.r);
}

}  // namespace
}  // namespace rad
