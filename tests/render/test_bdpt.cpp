// Bidirectional path tracing against the path tracer, path-type images and Neumann terms.
//
// Both integrators are unbiased estimators of the same pixel values, so their images differ only
// by noise: with per-pixel variance estimates vA and vB of the two means, E[(A − B)²] = vA + vB
// in every pixel. The image means must agree within 4σ of their noise and within 1% (the issue's
// tolerance: the renders are made quiet enough that 1% is at least 2.5σ, σ from the variance
// estimates, which stratification makes over-estimates), and the mean squared difference over the
// pixels must stay below 2·mean(vA + vB): the factor 2 leaves room for the variance estimates'
// own noise (they are sums of few heavy-tailed squares), while a bias of a few percent in the
// bright pixels would exceed it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "radiosity/render/bdpt.h"
#include "radiosity/render/path_renderer.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";
const std::string kGlass =
    std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box_mirror_glass.obj";
const std::string kFurnace = std::string(RADIOSITY_DATA_DIR) + "/tests/furnace_box.obj";

// A scene's triangles as the path tracer sees them (no radiosity solve).
struct PathScene {
  Scene scene;
  std::unique_ptr<PatchMesh> mesh;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
};

std::unique_ptr<PathScene> loadPathScene(const std::string& path) {
  auto s = std::make_unique<PathScene>();
  s->scene = loadObjScene(path);
  s->mesh = std::make_unique<PatchMesh>(buildPatchMesh(s->scene));
  s->caster = std::make_unique<RayCaster>(*s->mesh);
  s->view = std::make_unique<RenderScene>(s->scene, *s->mesh, *s->caster);
  return s;
}

Camera cornellCamera(int size) {
  Camera c = loadCamera(std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.camera.json");
  c.width = c.height = size;
  return c;
}

RenderSettings quiet(int spp, uint64_t seed = 1) {
  RenderSettings s;
  s.samplesPerPixel = spp;
  s.seed = seed;
  s.showProgress = false;
  return s;
}

double meanOf(const ImageRgb& image) {
  double sum = 0;
  for (const Rgb& p : image.pixels) sum += p.sum();
  return sum / (3.0 * image.pixels.size());
}

// Standard error of the image mean from the per-pixel variances.
double meanSigma(const ImageRgb& variance) {
  double sum = 0;
  for (const Rgb& v : variance.pixels) sum += v.sum();
  const double n = 3.0 * variance.pixels.size();
  return std::sqrt(sum) / n;
}

// `onePercent`: also hold the means to 1% (the renders must then be quiet enough for that).
void expectAgree(const RenderOutput& a, const RenderOutput& b, bool onePercent = true) {
  const double meanA = meanOf(a.image), meanB = meanOf(b.image);
  const double sigma = std::hypot(meanSigma(a.variance), meanSigma(b.variance));
  EXPECT_NEAR(meanB, meanA, 4 * sigma);
  if (onePercent) {
    ASSERT_LT(2.5 * sigma, 0.01 * meanA)
        << "too few samples for a 1% test: sigma A " << meanSigma(a.variance) << ", B "
        << meanSigma(b.variance);
    EXPECT_NEAR(meanB, meanA, 0.01 * meanA);
  }
  double squared = 0, expected = 0;
  for (size_t p = 0; p < a.image.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      const double d = a.image.pixels[p][c] - b.image.pixels[p][c];
      squared += d * d;
      expected += a.variance.pixels[p][c] + b.variance.pixels[p][c];
    }
  const double n = 3.0 * a.image.pixels.size();
  EXPECT_LT(std::sqrt(squared / n), std::sqrt(2 * expected / n))
      << "RMSE " << std::sqrt(squared / n) << " vs expected " << std::sqrt(expected / n);
}

class BdptAgreesWithPath : public ::testing::TestWithParam<std::string> {};

TEST_P(BdptAgreesWithPath, MeanAndPixels) {
  const auto s = loadPathScene(GetParam());
  const Camera camera = cornellCamera(32);  // enough pixels that 1% is ≥ 2.5σ on both boxes
  const PathTracer path(*s->view);
  const Bdpt bdpt(*s->view, camera);
  const RenderOutput a = renderPathImage(camera, path, quiet(1024, 1), nullptr).full;
  const RenderOutput b = renderPathImage(camera, bdpt, quiet(128, 2), nullptr).full;
  expectAgree(a, b);
}

INSTANTIATE_TEST_SUITE_P(CornellBoxes, BdptAgreesWithPath, ::testing::Values(kCornell, kGlass));

// Without a splat image BDPT drops light tracing (t = 1) and weighs the remaining strategies
// only: still unbiased, so it agrees with the path tracer too (within its noise: the light's
// edge pixels make it too noisy for a 1% test at this cost).
TEST(Bdpt, WithoutLightTracingStillAgrees) {
  const auto s = loadPathScene(kCornell);
  const Camera camera = cornellCamera(24);
  const PathTracer path(*s->view);
  const Bdpt bdpt(*s->view, camera);
  const RenderOutput a = renderPathImage(camera, path, quiet(1024, 1), nullptr).full;
  const RenderOutput b = renderImage(camera, bdpt, quiet(256, 3));
  expectAgree(a, b, false);
}

// Caustics LS+DE: the path tracer finds them only by hitting the light through the glass by
// chance, BDPT's light tracing by following the light. Same samples per pixel, the summed
// per-pixel variance of the caustic image must be far lower (at least 4×).
TEST(Bdpt, CausticsHaveLowerVarianceThanPathTracing) {
  const auto s = loadPathScene(kGlass);
  const Camera camera = cornellCamera(24);
  const ExpressionBinning caustics(PathExpression::parse("LS+DE"));
  const PathTracer path(*s->view);
  const Bdpt bdpt(*s->view, camera);
  const RenderOutput a = renderPathImage(camera, path, quiet(32), &caustics).bins[0];
  const RenderOutput b = renderPathImage(camera, bdpt, quiet(32), &caustics).bins[0];
  double va = 0, vb = 0;
  for (size_t p = 0; p < a.variance.pixels.size(); ++p) {
    va += a.variance.pixels[p].sum();
    vb += b.variance.pixels[p].sum();
  }
  EXPECT_GT(meanOf(b.image), 0);
  EXPECT_LT(4 * vb, va) << "bdpt " << vb << ", path " << va;
}

// The path types LE, LDE, LD(D|S)+E and LS(D|S)*E partition L(D|S)*E: with the same seed the
// random numbers are drawn the same whatever the binning, so their images sum to the full one
// up to float rounding.
class PartitionSums : public ::testing::TestWithParam<bool> {};

TEST_P(PartitionSums, ToTheFullImage) {
  const auto s = loadPathScene(kGlass);
  const Camera camera = cornellCamera(16);
  std::unique_ptr<PathIntegrator> integrator;
  if (GetParam())
    integrator = std::make_unique<Bdpt>(*s->view, camera);
  else
    integrator = std::make_unique<PathTracer>(*s->view);
  const ImageRgb full = renderPathImage(camera, *integrator, quiet(16), nullptr).full.image;
  ImageRgb sum(camera.width, camera.height);
  for (const char* expression : {"LE", "LDE", "LD(D|S)+E", "LS(D|S)*E"}) {
    const ExpressionBinning part(PathExpression::parse(expression));
    const ImageRgb image = renderPathImage(camera, *integrator, quiet(16), &part).bins[0].image;
    EXPECT_GT(meanOf(image), 0) << expression;  // each part is seen in this scene
    for (size_t p = 0; p < sum.pixels.size(); ++p) sum.pixels[p] += image.pixels[p];
  }
  for (size_t p = 0; p < sum.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sum.pixels[p][c], full.pixels[p][c], 1e-9 * (1 + full.pixels[p][c])) << p;
}

INSTANTIATE_TEST_SUITE_P(PathAndBdpt, PartitionSums, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "bdpt" : "path"; });

// The path tracer splats nothing: its full image from renderPathImage is renderImage's exactly.
TEST(PathRenderer, FullImageIsRenderImagesForThePathTracer) {
  const auto s = loadPathScene(kCornell);
  const Camera camera = cornellCamera(8);
  const PathTracer path(*s->view);
  const BounceBinning bins(2);
  const RenderOutput a = renderImage(camera, path, quiet(4));
  const RenderOutput b = renderPathImage(camera, path, quiet(4), &bins).full;
  for (size_t p = 0; p < a.image.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(a.image.pixels[p][c], b.image.pixels[p][c]);
}

// Neumann terms: bounce images 0..K plus the paths of more than K bounces sum to the full image;
// in the furnace (closed box, ρ = 0.5, Ke = 1, E = π Ke) term k is E ρ^k / π = 0.5^k in every
// pixel, within 5σ. σ is the larger of the pixel's own estimate and the image's pooled one: the
// furnace's pixels all estimate the same value with similar noise, and with Russian roulette the
// higher terms are skewed (rare large samples), so one pixel's estimate alone can fall short.
// Parameter: 0 path tracing, 1 BDPT with the power heuristic, 2 BDPT with the balance heuristic
// (both must weigh every path's strategies to a sum of 1).
class NeumannTerms : public ::testing::TestWithParam<int> {};

TEST_P(NeumannTerms, SumToTheFullImageAndMatchTheFurnace) {
  const auto s = loadPathScene(kFurnace);
  Camera camera;
  camera.position = {0.5, 0.45, 0.3};
  camera.lookAt = {0.7, 0.6, 1.0};
  camera.vfovDegrees = 100;
  camera.width = camera.height = 8;
  std::unique_ptr<PathIntegrator> integrator;
  if (GetParam() == 0)
    integrator = std::make_unique<PathTracer>(*s->view);
  else
    integrator = std::make_unique<Bdpt>(
        *s->view, camera,
        BdptOptions{GetParam() == 1 ? MisHeuristic::Power : MisHeuristic::Balance});
  constexpr int K = 3;
  const BounceBinning bounces(K);
  const PathRenderOutput out = renderPathImage(camera, *integrator, quiet(128), &bounces);
  const ExpressionBinning rest(PathExpression::parse("L(D|S)(D|S)(D|S)(D|S)+E"));
  const ImageRgb more = renderPathImage(camera, *integrator, quiet(128), &rest).bins[0].image;
  for (size_t p = 0; p < more.pixels.size(); ++p)
    for (int c = 0; c < 3; ++c) {
      double sum = more.pixels[p][c];
      for (int k = 0; k <= K; ++k) sum += out.bins[k].image.pixels[p][c];
      const double full = out.full.image.pixels[p][c];
      EXPECT_NEAR(sum, full, 1e-9 * (1 + full)) << p;
    }
  for (int k = 0; k <= K; ++k) {
    const double expected = std::pow(0.5, k);
    const double pooled = meanSigma(out.bins[k].variance) * std::sqrt(3.0 * more.pixels.size());
    for (size_t p = 0; p < more.pixels.size(); ++p)
      for (int c = 0; c < 3; ++c) {
        const double sigma = std::max(pooled, std::sqrt(out.bins[k].variance.pixels[p][c]));
        EXPECT_NEAR(out.bins[k].image.pixels[p][c], expected, 5 * sigma + 1e-12)
            << "term " << k << " pixel " << p;
      }
    EXPECT_NEAR(meanOf(out.bins[k].image), expected, 4 * meanSigma(out.bins[k].variance) + 1e-12)
        << "term " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(PathAndBdpt, NeumannTerms, ::testing::Values(0, 1, 2),
                         [](const auto& info) {
                           return std::string(info.param == 0   ? "path"
                                              : info.param == 1 ? "bdpt_power"
                                                                : "bdpt_balance");
                         });

}  // namespace
}  // namespace rad
