// The first shot of point, spot, directional, sky and environment lights in the radiosity solve,
// against analytic answers: B = ρ E_d on surfaces that see no other surface, E_d the element's
// area mean of the formula (within the bound its stratified estimate guarantees), the values at
// the receiver points exact up to rounding, and the Monte Carlo estimates of the skies and
// environments within 4σ (5 standard errors) of their expectation.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/formfactors/receiver_points.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/light_shapes.h"
#include "radiosity/scene/scene.h"
#include "tests/support/clear_sky_reference.h"
#include "tests/support/hdr_writer.h"
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

SolveOptions quickOptions(int elements = 128) {
  SolveOptions options;
  options.targetElements = elements;
  options.raysPerElement = 64;
  options.threads = 2;
  return options;
}

Light pointLight(const Eigen::Vector3d& position, const Rgb& intensity) {
  Light light;
  light.type = LightType::Point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

// I cosθ / r² at x on a surface with normal n (a spot's falloff included).
Rgb pointIrradiance(const Light& light, const Eigen::Vector3d& x, const Eigen::Vector3d& n) {
  const Eigen::Vector3d d = light.position - x;
  const double falloff =
      light.type == LightType::Spot ? spotFalloff(light, light.direction.dot(-d.normalized())) : 1;
  return light.intensity * (falloff * std::max(0.0, n.dot(d.normalized())) / d.squaredNorm());
}

// The element's area mean of the irradiance, and how far the solver's estimate may be from it.
// The solver takes one point in each of kAreaStrata² equal-area strata of the element (a grid over
// the (s, t) square, which x = (1 − √s) c0 + √s (1 − t) c1 + √s t c2 maps onto the triangle
// preserving area); each point's value and its stratum's mean lie within the stratum's range, so
// the estimate is within the mean of those ranges of the true mean. The mean comes from a 64 × 64
// grid of midpoints, the ranges from the 65 × 65 lattice of their cells' corners, a stratum's own
// edges among them (where a spot's edge crosses an element, the light peaks at its corner), 5%
// wider for the lattice's own coarseness.
struct AreaMean {
  Rgb mean;
  double bound = 0;  // on each channel, relative to the channel's mean
};
AreaMean areaMean(const Light& light, const std::array<Eigen::Vector3d, 3>& c,
                  const Eigen::Vector3d& n) {
  constexpr int kGrid = 64, kPerStratum = kGrid / kAreaStrata;
  auto at = [&](double s, double t) {
    const double r = std::sqrt(s);
    return pointIrradiance(light, (1 - r) * c[0] + r * (1 - t) * c[1] + r * t * c[2], n);
  };
  AreaMean out;
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      out.mean += at((i + 0.5) / kGrid, (j + 0.5) / kGrid) / (kGrid * kGrid);
  std::vector<double> lo(kAreaStrata * kAreaStrata, 1e300), hi(kAreaStrata * kAreaStrata, 0);
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const double e = at(static_cast<double>(i) / kGrid, static_cast<double>(j) / kGrid).r;
      // A lattice point on a strata boundary belongs to the strata on both sides of it.
      for (int si = std::max(0, (i - 1) / kPerStratum);
           si <= std::min(kAreaStrata - 1, i / kPerStratum); ++si)
        for (int sj = std::max(0, (j - 1) / kPerStratum);
             sj <= std::min(kAreaStrata - 1, j / kPerStratum); ++sj) {
          const int stratum = si + kAreaStrata * sj;
          lo[stratum] = std::min(lo[stratum], e);
          hi[stratum] = std::max(hi[stratum], e);
        }
    }
  double range = 0;
  for (size_t k = 0; k < lo.size(); ++k) range += (hi[k] - lo[k]) / lo.size();
  out.bound = out.mean.r > 0 ? 1.05 * range / out.mean.r + 1e-12 : 0;
  return out;
}

void expectNear(const Rgb& got, const Rgb& want, double relative, int element) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got[c], want[c], relative * std::abs(want[c]) + 1e-300)
        << "element " << element << " channel " << c;
}

TEST(DirectLight, PointLightOverAPlaneGivesRhoICosOverRSquaredAveragedOverTheElement) {
  const Light light = pointLight({0.3, 0.8, -0.2}, {10, 20, 30});
  const SolveResult result = solveScene(floorScene({light}), quickOptions());
  const Solution& s = result.solution;
  ASSERT_GT(s.mesh->elementCount(), 50);
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    const AreaMean want = areaMean(light, s.mesh->corners(e), s.mesh->normal(e));
    expectNear(s.radiosity[e], kRho * want.mean, want.bound, e);
  }
  // One shadow ray per point, one point per stratum (hemisphere factors keep no receiver points).
  EXPECT_EQ(result.report.directLightRays, kAreaStrata * kAreaStrata * s.mesh->elementCount());
}

// Where the solution keeps B at the receiver points (analytic factors, 3 points), each point shows
// its own direct light: the points differ by ρ × the difference of their irradiance, and their
// mean is the element's B.
TEST(DirectLight, ReceiverPointValuesShowTheDirectLightAtEachPoint) {
  const Light light = pointLight({0.3, 0.4, -0.2}, {10, 20, 30});
  SolveOptions options = quickOptions();
  options.formFactors = FormFactorMethod::Analytic;
  options.shadowRays = 1;
  const SolveResult result = solveScene(floorScene({light}), options);
  const Solution& s = result.solution;
  ASSERT_EQ(s.pointRadiosity.size(), static_cast<size_t>(s.mesh->elementCount()));
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    const auto points = receiverPoints(s.mesh->corners(e));
    std::array<Rgb, 3> atPoint;
    Rgb pointMean, shownMean;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d d = light.position - points[k];
      atPoint[k] = kRho * light.intensity * (d.normalized().y() / d.squaredNorm());
      pointMean += atPoint[k] / 3;
      shownMean += s.pointRadiosity[e][k] / 3;
    }
    expectNear(shownMean, s.radiosity[e], 1e-12, e);
    for (int k = 0; k < 3; ++k)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(s.pointRadiosity[e][k][ch] - s.radiosity[e][ch], (atPoint[k] - pointMean)[ch],
                    1e-12 * s.radiosity[e][ch])
            << "element " << e << " point " << k;
  }
}

TEST(DirectLight, ALightBehindAOneSidedSurfaceDoesNotLightIt) {
  const SolveResult result =
      solveScene(floorScene({pointLight({0, -1, 0}, {10, 10, 10})}), quickOptions());
  for (const Rgb& b : result.solution.radiosity) EXPECT_TRUE(b.isZero());
  EXPECT_EQ(result.report.directLightRays, 0u);  // back-facing points get no rays
}

TEST(DirectLight, SpotIsZeroOutsideItsOuterConeAndAPointLightInsideItsInnerCone) {
  Light spot = pointLight({0, 1, 0}, {5, 5, 5});
  spot.type = LightType::Spot;
  spot.direction = {0, -1, 0};
  spot.cosOuter = std::cos(30 * M_PI / 180);
  spot.cosInner = std::cos(20 * M_PI / 180);
  const SolveResult result = solveScene(floorScene({spot}), quickOptions(512));
  const Solution& s = result.solution;
  Light asPoint = spot;
  asPoint.type = LightType::Point;
  int outside = 0, inside = 0, between = 0;
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    const auto c = s.mesh->corners(e);
    const Eigen::Vector3d n = s.mesh->normal(e);
    const AreaMean withCone = areaMean(spot, c, n), withoutCone = areaMean(asPoint, c, n);
    if (withCone.mean.isZero()) {  // wholly outside the outer cone
      ++outside;
      EXPECT_TRUE(s.radiosity[e].isZero()) << "element " << e;
    } else if (withCone.mean.r == withoutCone.mean.r) {  // wholly inside the inner cone
      ++inside;
      expectNear(s.radiosity[e], kRho * withoutCone.mean, withoutCone.bound, e);
    } else {
      ++between;
      expectNear(s.radiosity[e], kRho * withCone.mean, withCone.bound, e);
    }
  }
  EXPECT_GT(outside, 0);
  EXPECT_GT(inside, 0);
  EXPECT_GT(between, 0);
}

// A plane tilted 40° about x, its normal 40° from the sun's direction.
Scene tiltedScene(const std::vector<Light>& lights) {
  Scene scene = sceneWith(lights);
  const double a = 40 * M_PI / 180;
  const Eigen::Vector3d u(1, 0, 0), v(0, std::sin(a), -std::cos(a));  // n = u × v
  addQuad(scene, {-u - v, u - v, u + v, -u + v});
  return scene;
}

TEST(DirectLight, DirectionalLightGivesRhoECosThetaOnATiltedPlane) {
  for (const double diameter : {0.0, 0.53}) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0, -1, 0};
    sun.irradiance = {100, 200, 300};
    sun.angularDiameterDegrees = diameter;
    const SolveResult result = solveScene(tiltedScene({sun}), quickOptions());
    const Solution& s = result.solution;
    // Every ray over the sun's disc (half-angle h) has a cosine within cosθ·(1 ± tanθ·sin h + h²)
    // of the centre's, so their mean does too; a point sun is exact.
    const double h = 0.5 * diameter * M_PI / 180;
    const double tolerance = diameter > 0 ? std::tan(40 * M_PI / 180) * std::sin(h) + h * h : 1e-12;
    for (int e = 0; e < s.mesh->elementCount(); ++e) {
      const double cosTheta = s.mesh->normal(e).dot(-sun.direction);
      ASSERT_NEAR(cosTheta, std::cos(40 * M_PI / 180), 1e-12);
      expectNear(s.radiosity[e], kRho * sun.irradiance * cosTheta, tolerance, e);
    }
  }
}

Light sky(const Rgb& radiance) {
  Light light;
  light.type = LightType::Sky;
  light.radiance = radiance;
  return light;
}

TEST(DirectLight, UniformSkyOnAnOpenUpwardPlaneIsRhoPiL) {
  const Light light = sky({1, 2, 3});
  const SolveResult result = solveScene(floorScene({light}), quickOptions());
  for (int e = 0; e < result.solution.mesh->elementCount(); ++e)
    expectNear(result.solution.radiosity[e], kRho * light.radiance * M_PI, 1e-12, e);
}

// CIE overcast, L(θ) = L_z (1 + 2 cos θ)/3: E = 7πL_z/9 on an open upward plane. Each ray's
// value π L(θ) lies in [π/3, π] L_z, so its standard deviation is at most π/3 L_z, and the mean
// over all elements' rays (64 per receiver point, 3 points each) lies within 4 such σ of it.
TEST(DirectLight, CieOvercastSkyOnAnOpenUpwardPlaneIsSevenNinthsRhoPiLzWithinFourSigma) {
  Light light = sky({1, 2, 3});
  light.skyModel = SkyModel::CieOvercast;
  const SolveResult result = solveScene(floorScene({light}), quickOptions());
  const Solution& s = result.solution;
  Rgb mean;
  for (int e = 0; e < s.mesh->elementCount(); ++e) mean += s.radiosity[e];
  mean = mean / s.mesh->elementCount();
  const double rays = 64.0 * 3 * s.mesh->elementCount();
  for (int c = 0; c < 3; ++c) {
    const double want = kRho[c] * light.radiance[c] * 7 * M_PI / 9;
    EXPECT_NEAR(mean[c], want, 4 * kRho[c] * light.radiance[c] * M_PI / 3 / std::sqrt(rays))
        << "channel " << c;
  }
}

TEST(DirectLight, UniformSkyOnALoneVerticalQuadIsHalfRhoPiLWithinFourSigma) {
  Scene scene = sceneWith({sky({1, 1, 1})});
  addQuad(scene, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});  // facing +z
  const SolveResult result = solveScene(scene, quickOptions());
  const Solution& s = result.solution;
  const int n = s.mesh->elementCount();
  // Each ray is a Bernoulli trial of p = 1/2 (above the horizon or not): σ of a mean of m trials
  // is 0.5/√m (stratification only lowers it; here the horizon falls on strata boundaries).
  const double perElement = 4 * 0.5 / std::sqrt(3.0 * 64);
  double sum = 0, area = 0;
  for (int e = 0; e < n; ++e) {
    const double fraction = s.radiosity[e].r / (kRho.r * M_PI);
    EXPECT_NEAR(fraction, 0.5, perElement) << "element " << e;
    sum += fraction * s.mesh->area(e);
    area += s.mesh->area(e);
  }
  EXPECT_NEAR(sum / area, 0.5, 4 * 0.5 / std::sqrt(3.0 * 64 * n));
}

// A plane tilted β = 40° from up sees the fraction (1 + cos β) / 2 of its cosine-weighted
// directions above the horizon. The rays come from streams keyed by (seed, element, point): the
// same seed gives the same solution on any thread count, another seed another estimate.
TEST(DirectLight, SkyOnATiltedPlaneIsWithinFourSigmaAndDependsOnTheSeedOnly) {
  const Scene scene = tiltedScene({sky({1, 1, 1})});
  SolveOptions one = quickOptions(), two = quickOptions(), other = quickOptions();
  one.threads = 1;
  other.seed = 7;
  const SolveResult first = solveScene(scene, one);
  const auto& a = first.solution.radiosity;
  const auto b = solveScene(scene, two).solution.radiosity;
  const auto c = solveScene(scene, other).solution.radiosity;
  ASSERT_EQ(a.size(), b.size());
  bool differs = false;
  for (size_t e = 0; e < a.size(); ++e) {
    EXPECT_EQ(a[e].r, b[e].r) << "element " << e;
    differs |= a[e].r != c[e].r;
  }
  EXPECT_TRUE(differs);
  const double p = (1 + std::cos(40 * M_PI / 180)) / 2;
  double mean = 0;
  const PatchMesh& mesh = *first.solution.mesh;
  for (size_t e = 0; e < a.size(); ++e)
    mean += a[e].r / (kRho.r * M_PI) * mesh.area(static_cast<int>(e)) / mesh.totalArea();
  EXPECT_NEAR(mean, p, 4 * std::sqrt(p * (1 - p) / (3.0 * 64 * a.size())));
}

// The six faces of the unit cube, looking in: no light from outside reaches them.
void addClosedUnitBox(Scene& scene) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (const auto& f : std::vector<std::array<int, 4>>{
           {0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}})
    addQuad(scene, {p[f[0]], p[f[1]], p[f[2]], p[f[3]]});
}

TEST(DirectLight, UniformSkyDoesNotEnterAClosedBox) {
  Scene scene = sceneWith({sky({1, 1, 1})});
  addClosedUnitBox(scene);
  const SolveResult result = solveScene(scene, quickOptions(384));
  for (int e = 0; e < result.solution.mesh->elementCount(); ++e)
    EXPECT_TRUE(result.solution.radiosity[e].isZero()) << "element " << e;
  EXPECT_GT(result.report.directLightRays, 0u);
}

// Environment lights and the CIE clear sky are sampled half by the map's luminance, half
// cosine-weighted, combined by the balance heuristic (direct_light_stage.h): each ray's term
// L cosθ / (p_map + cosθ/π) lies in [0, π L_max], so a pair of them (one of each kind) has a
// standard deviation of at most π L_max, and the mean over all receiver points' 32 pairs each lies
// within 4 such σ/√pairs of E.
double mapTolerance(double maxRadiance, int elements) {
  return 4 * M_PI * maxRadiance / std::sqrt(32.0 * 3 * elements);
}

// The area-weighted mean radiosity of the elements facing `normal`, and their count.
Rgb meanRadiosity(const Solution& s, const Eigen::Vector3d& normal, int& count) {
  Rgb sum;
  double area = 0;
  count = 0;
  for (int e = 0; e < s.mesh->elementCount(); ++e)
    if (s.mesh->normal(e).dot(normal) > 0.999) {
      sum += s.radiosity[e] * s.mesh->area(e);
      area += s.mesh->area(e);
      ++count;
    }
  return sum / area;
}

// An environment light read from a lights file beside a Radiance HDR image the test writes.
Light environmentFromFile(const std::string& name, int width, int height,
                          const std::vector<Rgb>& texels) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("radiosity_env_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::create_directories(dir);
  testing::writeHdr((dir / "sky.hdr").string(), width, height, texels);
  std::ofstream(dir / "l.json") << R"({"lights": [{"type": "environment", "file": "sky.hdr"}]})";
  const std::vector<Light> lights = loadLights((dir / "l.json").string());
  std::filesystem::remove_all(dir);
  return lights.at(0);
}

// A constant environment L lights an open upward plane with E = πL (the ground half is below its
// horizon) and a lone vertical one with πL too (it sees half the sky and half the ground, both
// L), where a uniform sky gives πL/2.
TEST(DirectLight, ConstantEnvironmentGivesRhoPiLFacingUpAndSideways) {
  const Light light = environmentFromFile("constant", 16, 8, std::vector<Rgb>(128, Rgb::all(2)));
  ASSERT_EQ(skyRadiance(light, {0, -1, 0}).r, 2);  // read exactly, the ground half too
  Scene scene = floorScene({light});
  // Facing +z, below the floor and beyond it: neither sees the other nor blocks its view.
  addQuad(scene, {{-1, -12, 2}, {1, -12, 2}, {1, -10, 2}, {-1, -10, 2}});
  const SolveResult result = solveScene(scene, quickOptions(256));
  const Solution& s = result.solution;
  for (const Eigen::Vector3d& n : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)}) {
    int count = 0;
    const Rgb mean = meanRadiosity(s, n, count);
    ASSERT_GT(count, 50);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(mean[c], kRho[c] * M_PI * 2, kRho[c] * mapTolerance(2, count)) << n.transpose();
  }
}

TEST(DirectLight, EnvironmentDoesNotEnterAClosedBox) {
  Scene scene = sceneWith({environmentFromFile("box", 16, 8, std::vector<Rgb>(128, Rgb::all(1)))});
  addClosedUnitBox(scene);
  const SolveResult result = solveScene(scene, quickOptions(384));
  for (int e = 0; e < result.solution.mesh->elementCount(); ++e)
    EXPECT_TRUE(result.solution.radiosity[e].isZero()) << "element " << e;
  EXPECT_GT(result.report.directLightRays, 0u);
}

// An image bright (L) above the horizon and black below is the uniform sky: ρπL on an open upward
// plane, ρπL/2 on a lone vertical one, each mean within the bound above.
TEST(DirectLight, EnvironmentBrightOnlyAboveTheHorizonIsTheUniformSky) {
  std::vector<Rgb> texels(16 * 8);
  std::fill(texels.begin(), texels.begin() + 16 * 4, Rgb::all(1));
  const Light light = environmentFromFile("half", 16, 8, texels);
  Scene scene = floorScene({light});
  // Facing +z, below the floor and beyond it: neither sees the other nor blocks its view.
  addQuad(scene, {{-1, -12, 2}, {1, -12, 2}, {1, -10, 2}, {-1, -10, 2}});
  const Solution s = solveScene(scene, quickOptions(256)).solution;
  int up = 0, side = 0;
  const double floor = meanRadiosity(s, {0, 1, 0}, up).r;
  const double wall = meanRadiosity(s, {0, 0, 1}, side).r;
  ASSERT_GT(std::min(up, side), 50);
  EXPECT_NEAR(floor, kRho.r * M_PI, kRho.r * mapTolerance(1, up));
  EXPECT_NEAR(wall, kRho.r * M_PI / 2, kRho.r * mapTolerance(1, side));
}

// The CIE clear sky's irradiance on an open upward plane (tests/support/clear_sky_reference.h).
// Every element's estimate is independent and alike (nothing shadows), so their mean lies within
// 5 standard errors (from their spread) of ρE.
TEST(DirectLight, CieClearSkyOnAnOpenUpwardPlaneMatchesTheIntegratedFormula) {
  const double e = 35 * M_PI / 180;
  const Light light = cieClearSky({1, 2, 3}, {std::cos(e) * 0.6, -std::sin(e), std::cos(e) * 0.8});
  const double want = testing::clearSkyUpwardIrradiance(35);
  const Solution s = solveScene(floorScene({light}), quickOptions()).solution;
  const int n = s.mesh->elementCount();
  double sum = 0, squares = 0;
  for (int e2 = 0; e2 < n; ++e2) {
    const double v = s.radiosity[e2].r / (kRho.r * light.radiance.r);
    sum += v;
    squares += v * v;
  }
  const double mean = sum / n, sigma = std::sqrt((squares / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, want, 5 * sigma);
  EXPECT_LT(sigma, 0.01 * want);  // the map's sampling keeps it smooth
  std::printf("clear sky, sun at 35°: E/L_z %.5f (formula %.5f) ± %.5f\n", mean, want, sigma);
}

// The first shot enters the solve as emission: a panel that no light reaches directly (it faces
// down, below the sky's horizon) is lit by the floor the sky lights.
TEST(DirectLight, InterreflectionCarriesTheFirstShotOn) {
  Scene scene = floorScene({sky({1, 1, 1})});
  addQuad(scene, {{1.5, 1, -0.5}, {2.5, 1, -0.5}, {2.5, 1, 0.5}, {1.5, 1, 0.5}});  // facing down
  const SolveResult result = solveScene(scene, quickOptions());
  const Solution& s = result.solution;
  double panel = 0;
  for (int e = 0; e < s.mesh->elementCount(); ++e)
    if (s.mesh->normal(e).y() < 0) panel = std::max(panel, s.radiosity[e].r);
  EXPECT_GT(panel, 0);
  EXPECT_LT(panel, kRho.r * M_PI * kRho.r);  // at most ρ × the floor's B
}

// Adaptive refinement recomputes the first shot on the split elements.
TEST(DirectLight, RefinedElementsGetTheirOwnDirectLight) {
  const Light light = pointLight({0.1, 0.3, 0.05}, {1, 1, 1});
  SolveOptions options = quickOptions(64);
  options.formFactors = FormFactorMethod::Analytic;
  options.shadowRays = 1;
  options.refineThreshold = 0.05;
  options.refinePasses = 2;
  const SolveResult result = solveScene(floorScene({light}), options);
  const Solution& s = result.solution;
  ASSERT_GT(result.report.refinementPasses, 0);
  ASSERT_GT(s.mesh->elementCount(), result.report.elementsBeforeRefinement);
  for (int e = 0; e < s.mesh->elementCount(); ++e) {
    const AreaMean want = areaMean(light, s.mesh->corners(e), s.mesh->normal(e));
    expectNear(s.radiosity[e], kRho * want.mean, want.bound, e);
  }
}

// The element's E_d is its area mean, also where the light pools along an edge. A sun straight
// down, and a roof at y = 0.5 over all of the unit floor but the strip x < 0.15: the floor's two
// triangles, (0,0)-(0,1)-(1,1) and (0,0)-(1,1)-(1,0) in (x, z), have lit fractions
// (0.15 − 0.15²/2) / 0.5 = 0.2775 and (0.15²/2) / 0.5 = 0.0225, and all three receiver points of
// either (1/6 or more from x = 0) lie in the shadow. Over 64 seeds the stratified estimates
// average to those fractions within 4 standard errors.
TEST(DirectLight, LightAlongAnEdgeOfTheElementCountsByTheAreaItLights) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = {1, 1, 1};
  Scene scene = sceneWith({sun});
  addQuad(scene, {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
  addQuad(scene, {{0.15, 0.5, -0.1}, {0.15, 0.5, 1.1}, {1.1, 0.5, 1.1}, {1.1, 0.5, -0.1}});
  SolveOptions options = quickOptions();
  options.targetElements = 0;
  options.elementSize = 10;  // the input triangles stay the elements
  constexpr int kSeeds = 64;
  std::array<double, 2> sum{}, sumSquares{};
  for (int seed = 1; seed <= kSeeds; ++seed) {
    options.seed = seed;
    const SolveResult result = solveScene(scene, options);
    const Solution& s = result.solution;
    int floor = 0;
    for (int e = 0; e < s.mesh->elementCount(); ++e) {
      const Eigen::Vector3d c = s.mesh->centroid(e);
      if (c.y() > 0.25) continue;
      // The triangle with the edge x = 0 has its centroid at x = 1/3, the other at 2/3.
      const double fraction = s.radiosity[e].r / kRho.r;
      const int which = c.x() < 0.5 ? 0 : 1;
      sum[which] += fraction, sumSquares[which] += fraction * fraction;
      ++floor;
    }
    ASSERT_EQ(floor, 2);
  }
  const std::array<double, 2> want{0.2775, 0.0225};
  for (int k = 0; k < 2; ++k) {
    const double mean = sum[k] / kSeeds;
    const double variance = std::max(0.0, sumSquares[k] / kSeeds - mean * mean);
    const double standardError = std::sqrt(variance / (kSeeds - 1));
    EXPECT_NEAR(mean, want[k], 4 * standardError + 1e-9) << "triangle " << k;
    EXPECT_GT(mean, 0.5 * want[k]) << "triangle " << k;  // the receiver points alone give 0
  }
}

// With more point lights than kEveryPointLight, each area point casts one shadow ray, to a light
// picked by its unshadowed share. Eight lights: four above a roof that hides them from the whole
// floor, four under it. Over 64 seeds each floor element's B averages to ρ × the area mean of the
// four visible lights' irradiance within 4 standard errors, with 16 shadow rays per element.
TEST(DirectLight, ManyPointLightsShareOneShadowRayPerPointAndStayUnbiased) {
  std::vector<Light> lights, visible;
  for (int k = 0; k < 8; ++k) {
    const double a = k * 0.785398;
    const bool above = k % 2 == 0;
    lights.push_back(pointLight({0.6 * std::cos(a), above ? 1.0 : 0.5, 0.6 * std::sin(a)},
                                {1.0 + k, 2.0, 3.0 - 0.3 * k}));
    if (!above) visible.push_back(lights.back());
  }
  ASSERT_GT(lights.size(), kEveryPointLight);
  Scene scene = floorScene(lights);
  addQuad(scene, {{-1, 0.8, -1}, {-1, 0.8, 1}, {1, 0.8, 1}, {1, 0.8, -1}});  // the roof, facing up
  SolveOptions options = quickOptions();
  options.targetElements = 0;
  options.elementSize = 0.6;
  constexpr int kSeeds = 64;
  std::vector<Rgb> sum, sumSquares;
  std::vector<int> floorElements;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    options.seed = seed;
    const SolveResult result = solveScene(scene, options);
    const Solution& s = result.solution;
    if (floorElements.empty()) {
      for (int e = 0; e < s.mesh->elementCount(); ++e)
        if (s.mesh->centroid(e).y() < 0.4) floorElements.push_back(e);
      sum.assign(floorElements.size(), Rgb()), sumSquares.assign(floorElements.size(), Rgb());
      ASSERT_GT(floorElements.size(), 10u);
    }
    EXPECT_EQ(result.report.directLightRays,
              static_cast<uint64_t>(kAreaStrata * kAreaStrata) * s.mesh->elementCount());
    for (size_t i = 0; i < floorElements.size(); ++i) {
      const Rgb b = s.radiosity[floorElements[i]];
      sum[i] += b, sumSquares[i] += b * b;
    }
  }
  const SolveResult first = solveScene(scene, options);
  for (size_t i = 0; i < floorElements.size(); ++i) {
    const int e = floorElements[i];
    Rgb want;
    for (const Light& light : visible)
      want += kRho *
              areaMean(light, first.solution.mesh->corners(e), first.solution.mesh->normal(e)).mean;
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[i][c] / kSeeds;
      const double variance = std::max(0.0, sumSquares[i][c] / kSeeds - mean * mean);
      EXPECT_NEAR(mean, want[c], 4 * std::sqrt(variance / (kSeeds - 1)) + 1e-3 * want[c])
          << "element " << e << " channel " << c;
    }
  }
}

TEST(DirectLight, ASceneWithLightsAndNoEmissivePolygonIsAccepted) {
  Scene scene = floorScene({});
  EXPECT_THROW(requireEmitter(scene), InputError);
  scene.lights.push_back(sky({1, 1, 1}));
  EXPECT_NO_THROW(requireEmitter(scene));
}

}  // namespace
}  // namespace rad
