// Extended form factors: light carried to diffuse surfaces through mirrors and glass.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "radiosity/formfactors/specular_paths.h"
#include "radiosity/solvers/progressive_solver.h"

namespace rad {
namespace {

// Receiver: unit square at z = 0 facing up. Emitter: 0.5 × 0.5 at z = 0.25 facing up, beside it,
// so the receiver (below the emitter's plane) never sees it directly. Mirror: a large square at
// z = 1 facing down. The receiver sees the emitter only through the mirror, and no line from the
// receiver to the emitter's image passes through the emitter itself.
struct MirrorScene {
  PatchMesh mesh;
  std::vector<SpecularSurface> surfaces;
  static constexpr int kReceiver = 0, kEmitter = 1, kMirror = 2;
  const Rgb ks{0.9, 0.8, 0.7};

  MirrorScene()
      : mesh({{0, 0, 0},
              {1, 0, 0},
              {1, 1, 0},
              {0, 1, 0},
              {1.5, 0.25, 0.25},
              {2, 0.25, 0.25},
              {2, 0.75, 0.25},
              {1.5, 0.75, 0.25},
              {-3, -3, 1},
              {6, -3, 1},
              {6, 4, 1},
              {-3, 4, 1}},
             {{{0, 1, 2, 3}, kReceiver}, {{4, 5, 6, 7}, kEmitter}, {{8, 11, 10, 9}, kMirror}}) {
    mesh.subdivideUniform(0.05);
    surfaces.resize(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e)
      if (mesh.material(e) == kMirror)
        surfaces[e] = {SpecularSurface::Kind::Mirror, ks, Rgb::all(1), 1};
  }
};

// F from the receiver square to the emitter's mirror image (z = 1.75, facing down), by Gauss
// quadrature of the exact point-to-polygon factor: the independent reference.
double receiverToMirrorImage() {
  const std::vector<Eigen::Vector3d> image = {
      {1.5, 0.25, 1.75}, {1.5, 0.75, 1.75}, {2, 0.75, 1.75}, {2, 0.25, 1.75}};
  const double x5[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                        0.9061798459386640};
  const double w5[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                        0.4786286704993665, 0.2369268850561891};
  double f = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      f += w5[i] * w5[j] / 4 *
           pointToPolygonFormFactor({0.5 + 0.5 * x5[i], 0.5 + 0.5 * x5[j], 0}, {0, 0, 1}, image);
  return f;
}

TEST(ExtendedFormFactors, ReceiverLitOnlyThroughTheMirrorGetsKsTimesTheImageFormFactor) {
  MirrorScene scene;
  RayCaster rays(scene.mesh);
  const int raysPerElement = 20000;
  HemisphereFormFactors method(scene.mesh, rays, {raysPerElement, 5, {}, scene.surfaces});
  FormFactorCache cache(method);

  // One shot of the emitter's power, E = pi (Ke = 1), with receiver reflectance 0.5.
  RadiosityProblem problem;
  for (int e = 0; e < scene.mesh.elementCount(); ++e) {
    const int m = scene.mesh.material(e);
    problem.emission.push_back(m == MirrorScene::kEmitter ? Rgb::all(M_PI) : Rgb());
    problem.reflectance.push_back(m == MirrorScene::kReceiver ? Rgb::all(0.5) : Rgb());
    problem.area.push_back(scene.mesh.area(e));
  }
  ProgressiveSolver solver(problem, cache);
  int emitterElements = 0;
  for (int e = 0; e < scene.mesh.elementCount(); ++e)
    emitterElements += scene.mesh.material(e) == MirrorScene::kEmitter;
  for (int k = 0; k < emitterElements; ++k) solver.step();  // every emitter element shoots once

  double receivedArea = 0;
  Rgb radiosityTimesArea;
  for (int e = 0; e < scene.mesh.elementCount(); ++e)
    if (scene.mesh.material(e) == MirrorScene::kReceiver) {
      radiosityTimesArea += solver.solution()[e] * scene.mesh.area(e);
      receivedArea += scene.mesh.area(e);
    }
  const Rgb mean = radiosityTimesArea / receivedArea;
  const double f = receiverToMirrorImage();
  ASSERT_GT(f, 0.01);
  // Fraction of the emitter's rays reaching the receiver: p = A_R F_R,image / A_L (reciprocity).
  const double p = 1.0 * f / 0.25;
  const double sigmaP = std::sqrt(p * (1 - p) / (emitterElements * double(raysPerElement)));
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.5 * scene.ks[c] * M_PI * f;  // rho_R · Ks · E · F
    // B = rho Ks E p A_L / A_R, so its σ is rho Ks E σ_p A_L / A_R.
    EXPECT_NEAR(mean[c], expected, 4 * 0.5 * scene.ks[c] * M_PI * sigmaP * 0.25) << "channel " << c;
  }
  EXPECT_GT(method.specularRays(), 0u);
}

TEST(ExtendedFormFactors, DiffuseSceneCastsNoExtraRaysAndSameRows) {
  MirrorScene scene;  // geometry only: every surface diffuse below
  RayCaster rays(scene.mesh);
  std::vector<SpecularSurface> allDiffuse(scene.mesh.elementCount());
  HemisphereFormFactors plain(scene.mesh, rays, {256, 3});
  HemisphereFormFactors extended(scene.mesh, rays, {256, 3, {}, allDiffuse});
  for (int e = 0; e < scene.mesh.elementCount(); e += 7) {
    const FormFactorRow a = plain.computeRow(e), b = extended.computeRow(e);
    EXPECT_EQ(a.targets, b.targets);
    EXPECT_EQ(a.values, b.values);
    EXPECT_TRUE(b.tinted.empty());
  }
  EXPECT_EQ(plain.specularRays(), 0u);
  EXPECT_EQ(extended.specularRays(), 0u);
}

TEST(ExtendedFormFactors, FresnelAtNormalIncidenceAndTotalInternalReflection) {
  // ((n − 1)/(n + 1))² at normal incidence; 1 beyond the critical angle.
  EXPECT_NEAR(fresnelDielectric(1.0, 1.0, 1.5), 0.04, 1e-12);
  EXPECT_NEAR(fresnelDielectric(1.0, 1.5, 1.0), 0.04, 1e-12);
  EXPECT_EQ(fresnelDielectric(std::cos(50 * M_PI / 180), 1.5, 1.0), 1.0);  // critical angle 41.8°
  EXPECT_NEAR(fresnelDielectric(0.0, 1.0, 1.5), 1.0, 1e-12);               // grazing
}

// A corridor of two mirrors (Ks = 0.95) facing each other, 1 m apart, and a diffuse wall closing
// its far end 10 m away: a ray leaving at a shallow slope reaches the wall after about 40
// reflections, carrying 0.95^40 of its light. Past kSpecularRouletteAfter bounces it plays Russian
// roulette on its weight, so it arrives with weight 1 or not at all: the mean over many rays is
// still 0.95^bounces, and no ray ever carries more than 1 (rows conserve energy ray by ray). With
// the former cut-off at 16 bounces no ray arrived: a glass panel seen edge-on, which guides light
// the same way, rendered black.
TEST(ExtendedFormFactors, LongMirrorChainsCarryTheirLightOnAverageWithNoCutOff) {
  enum { kMirrorFloor, kMirrorCeiling, kWall, kSource };
  PatchMesh mesh({{0, 0, -1},
                  {0, 0, 1},
                  {10.5, 0, 1},
                  {10.5, 0, -1},  // y = 0, facing +y
                  {0, 1, -1},
                  {10.5, 1, -1},
                  {10.5, 1, 1},
                  {0, 1, 1},  // y = 1, facing −y
                  {10, 0, -1},
                  {10, 0, 1},
                  {10, 1, 1},
                  {10, 1, -1},  // x = 10, facing −x
                  {-5, -5, -5},
                  {-4, -5, -5},
                  {-4, -4, -5},
                  {-5, -4, -5}},  // out of the way
                 {{{0, 1, 2, 3}, kMirrorFloor},
                  {{4, 5, 6, 7}, kMirrorCeiling},
                  {{8, 9, 10, 11}, kWall},
                  {{12, 13, 14, 15}, kSource}});
  mesh.subdivideUniform(2.0);
  std::vector<SpecularSurface> surfaces(mesh.elementCount());
  std::vector<Eigen::Vector3d> normals(mesh.elementCount());
  int source = -1;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    normals[e] = mesh.normal(e);
    if (mesh.material(e) <= kMirrorCeiling)
      surfaces[e] = {SpecularSurface::Kind::Mirror, Rgb::all(0.95), Rgb::all(1), 1};
    if (mesh.material(e) == kSource) source = e;
  }
  const RayCaster rays(mesh);
  const Eigen::Vector3d origin(0.1, 0.5, 0), direction = Eigen::Vector3d(0.25, 1, 0).normalized();
  constexpr int kPaths = 10000;
  double sum = 0;
  int arrived = 0, bounces = 0;
  for (int k = 0; k < kPaths; ++k) {
    Rng rng(streamKey(7, k));
    int cast = 0;
    const SpecularPathEnd end =
        traceThroughSpecular(rays, normals, surfaces, origin, direction, source, rng, &cast);
    if (end.element < 0) continue;
    ASSERT_EQ(mesh.material(end.element), kWall);
    ASSERT_LE(end.weight.maxComponent(), 1 + 1e-12);
    ++arrived;
    bounces = end.specularBounces;  // the same for every ray: they all take the one path
    sum += end.weight.r;
  }
  ASSERT_GT(arrived, 0);
  EXPECT_GT(bounces, 30);
  // Per ray: 1 with probability p = 0.95^bounces (about 0.13), else 0: the standard error of the
  // mean is sqrt(p(1 − p)/kPaths), about 0.0033. Four of them:
  const double p = std::pow(0.95, bounces);
  EXPECT_NEAR(sum / kPaths, p, 4 * std::sqrt(p * (1 - p) / kPaths));
}

}  // namespace
}  // namespace rad
