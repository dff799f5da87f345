// The confidence map of a bake (docs/baking.md, "How far to trust each texel"): the mesh's
// displayed-error estimate against the true error of baked texels where the exact radiance is
// known (a point light over a plane: L = ρ I cosθ / (π r²), REFERENCES.md's point-to-surface
// law; the furnace: uniform B = E/(1−ρ)), its shrinking with the element size, and the per-texel
// gather's standard error against the spread of the texel's value over seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "meshing/lightmap_charts.h"
#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/rng.h"
#include "radiosity/output/image_io.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/output/lightmap_confidence.h"
#include "radiosity/output/vertex_colors_ply.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/visibility/ray_caster.h"
#include "tests/support/test_scenes.h"

namespace rad {
namespace {

const std::string kData = RADIOSITY_DATA_DIR;
const Rgb kRho{0.5, 0.4, 0.3};
const Eigen::Vector3d kLight{0.3, 1.0, -0.2};
const double kIntensity = 10;

// The floor y = 0 over [-2, 2]², facing up, under a point light of intensity kIntensity.
Scene pointLightOverFloor() {
  Light light;
  light.type = LightType::Point;
  light.position = kLight;
  light.intensity = Rgb::all(kIntensity);
  Scene scene = testing::greyScene(kRho, {light});
  testing::addPolygon(scene, {{-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}});
  return scene;
}

// The exact outgoing radiance of the floor at x: ρ I cosθ / (π r²).
Rgb exactRadiance(const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = kLight - x;
  return kRho * (kIntensity * d.normalized().y() / d.squaredNorm() / M_PI);
}

// One bake of a solution as `radiosity bake` forms it without a gather on untextured surfaces
// (radiosity/bake's texel_evaluation.cpp and confidence_pages.cpp): the interpolated values, the
// confidence map (each element's displayed error), and `exact` evaluated at every texel's point,
// on one page of `texelSize` texels.
struct Baked {
  Lightmap value, error, exact;
};
Baked bake(const Solution& solution, double texelSize,
           const std::function<Rgb(const Eigen::Vector3d&)>& exact) {
  const PatchMesh& mesh = *solution.mesh;
  const LightmapLayout layout =
      packLightmapCharts(buildLightmapCharts(mesh), {texelSize, 0, 2, 4096});
  EXPECT_EQ(layout.pages, 1);
  const VertexInterpolation interpolation(mesh, solution.problem.area);
  const std::vector<Rgb> vertices =
      interpolateVertexRadiance(interpolation, solution.radiosity, solution.pointRadiosity);
  std::vector<Rgb> radiance(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) radiance[e] = solution.radiosity[e] / M_PI;
  std::vector<std::array<Rgb, 3>> points = solution.pointRadiosity;
  for (auto& p : points)
    for (Rgb& b : p) b = b / M_PI;
  const std::vector<Rgb> elementError = displayedError(mesh, radiance, points);
  Baked b;
  b.value = bakeLightmap(mesh, layout, interpolation, vertices, 0);
  b.error = bakeLightmap(mesh, layout, interpolation, vertices, 0,
                         [&](int e, const Eigen::Vector3d&, size_t) { return elementError[e]; });
  b.exact = bakeLightmap(mesh, layout, interpolation, vertices, 0,
                         [&](int e, const Eigen::Vector3d& w, size_t) {
                           const auto c = mesh.corners(e);
                           return exact(w[0] * c[0] + w[1] * c[1] + w[2] * c[2]);
                         });
  return b;
}

SolveOptions floorOptions(int elements) {
  SolveOptions options;
  options.targetElements = elements;
  options.raysPerElement = 16;  // the floor sees nothing: its rays all escape
  options.threads = 2;
  return options;
}

// Per covered texel: the true error of the baked luminance and its estimate.
struct Errors {
  std::vector<double> truth, estimate;
  double meanTruth = 0, meanEstimate = 0;
};
Errors errorsOf(const Baked& b) {
  Errors out;
  for (size_t i = 0; i < b.value.state.size(); ++i) {
    if (b.value.state[i] != TexelState::Covered) continue;
    out.truth.push_back(
        std::fabs(b.value.radiance.pixels[i].luminance() - b.exact.radiance.pixels[i].luminance()));
    out.estimate.push_back(b.error.radiance.pixels[i].luminance());
    out.meanTruth += out.truth.back();
    out.meanEstimate += out.estimate.back();
  }
  out.meanTruth /= out.truth.size();
  out.meanEstimate /= out.estimate.size();
  return out;
}

TEST(LightmapConfidence, MeshEstimateTracksTheTrueErrorUnderAPointLightAndShrinksWithTheElements) {
  // Coarse elements (about 0.5 units on a 4-unit floor, the light 1 unit above), then half the
  // edge (four times the count).
  const SolveResult coarse = solveScene(pointLightOverFloor(), floorOptions(128));
  const SolveResult fine = solveScene(pointLightOverFloor(), floorOptions(512));
  const Baked c = bake(coarse.solution, 4.0 / 160, exactRadiance);
  const Baked f = bake(fine.solution, 4.0 / 160, exactRadiance);
  const Errors ce = errorsOf(c), fe = errorsOf(f);
  ASSERT_GT(ce.truth.size(), 10000u);
  // The solution's own error: each element's mean irradiance comes from 16 stratified points
  // (DirectLightStage), within a few per cent of the exact mean on these elements; taken as
  // 2% of the texel's exact value.
  for (const auto* run : {&c, &f}) {
    const Errors e = errorsOf(*run);
    size_t within = 0, covered = 0;
    for (size_t i = 0; i < run->value.state.size(); ++i) {
      if (run->value.state[i] != TexelState::Covered) continue;
      const double truth = std::fabs(run->value.radiance.pixels[i].luminance() -
                                     run->exact.radiance.pixels[i].luminance());
      const double noise = 0.02 * run->exact.radiance.pixels[i].luminance();
      within += truth <= 3 * run->error.radiance.pixels[i].luminance() + noise;
      ++covered;
    }
    // Most texels' true error lies within 3× the estimate (plus the solution's noise) ...
    EXPECT_GE(within, 0.8 * covered) << within << " of " << covered;
    std::printf("%zu of %zu covered texels within 3× the estimate + 2%%\n", within, covered);
    // ... and the estimate is not a vacuous bound: on average within a factor 3 of the truth.
    EXPECT_GT(e.meanEstimate, e.meanTruth / 3);
    EXPECT_LT(e.meanEstimate, 3 * e.meanTruth);
  }
  // Halving the element edge: between h (a border's one-sided vertex means) and h² (curvature)
  // for the displayed error, so the mean estimate falls by a factor 1.5 to 6 — and so does the
  // truth.
  const double ratio = ce.meanEstimate / fe.meanEstimate;
  EXPECT_GT(ratio, 1.5);
  EXPECT_LT(ratio, 6.0);
  const double trueRatio = ce.meanTruth / fe.meanTruth;
  EXPECT_GT(trueRatio, 1.5);
  std::printf("mean true error %.4g → %.4g, estimate %.4g → %.4g\n", ce.meanTruth, fe.meanTruth,
              ce.meanEstimate, fe.meanEstimate);
}

TEST(LightmapConfidence, FurnaceMeshEstimateIsZero) {
  SolveOptions options;
  options.scenePath = kData + "/tests/furnace_box.obj";
  options.solver = SolverKind::GaussSeidel;
  options.tolerance = 1e-8;
  options.targetElements = 300;
  options.raysPerElement = 64;
  options.threads = 2;
  const SolveResult result = solveScene(loadScene(options.scenePath), options);
  // Ke = 1, ρ = 0.5: L = 2 everywhere (REFERENCES.md, furnace).
  const Baked b =
      bake(result.solution, 1.0 / 32, [](const Eigen::Vector3d&) { return Rgb::all(2); });
  const Errors e = errorsOf(b);
  ASSERT_GT(e.truth.size(), 1000u);
  for (size_t i = 0; i < e.truth.size(); ++i) {
    ASSERT_LT(e.truth[i], 1e-5);
    ASSERT_LT(e.estimate[i], 1e-5);  // the field is uniform: nothing to interpolate wrong
  }
  const ConfidenceSummary s = summariseConfidence({b.value}, {b.error});
  EXPECT_EQ(s.texels, e.truth.size());
  EXPECT_LT(s.p95Relative, 1e-5);
  EXPECT_EQ(s.fractionAbove10Percent, 0.0);
}

TEST(LightmapConfidence, SummaryCountsCoveredLitTexels) {
  Lightmap value, error;
  value.radiance = ImageRgb(10, 1);
  error.radiance = ImageRgb(10, 1);
  value.state.assign(10, TexelState::Covered);
  for (int i = 0; i < 10; ++i) {
    value.radiance.pixels[i] = Rgb::all(2);
    error.radiance.pixels[i] = Rgb::all(0.02 * (i + 1));  // relative 1%, 2%, …, 10%
  }
  value.state[9] = TexelState::Dilated;  // not counted
  value.radiance.pixels[8] = Rgb();      // unlit: not counted
  // Left: 1%…8%; one more above 10% (30%).
  error.radiance.pixels[7] = Rgb::all(0.6);
  const ConfidenceSummary s = summariseConfidence({value}, {error});
  EXPECT_EQ(s.texels, 8u);
  EXPECT_NEAR(s.medianRelative, 0.05, 1e-12);
  EXPECT_NEAR(s.p95Relative, 0.30, 1e-12);
  EXPECT_NEAR(s.fractionAbove10Percent, 1.0 / 8, 1e-12);
}

TEST(LightmapConfidence, GatherStandardErrorMatchesTheSpreadOverSeeds) {
  SolveOptions options;
  options.scenePath = kData + "/cornell_box/cornell_box.obj";
  options.targetElements = 300;
  options.raysPerElement = 64;
  options.threads = 2;
  const SolveResult result = solveScene(loadScene(options.scenePath), options);
  const Solution& solution = result.solution;
  const PatchMesh& mesh = *solution.mesh;
  const RayCaster caster(mesh, solution.scene);
  const RenderScene view(solution.scene, mesh, caster);
  const FinalGather gather(view, solution.radiosity, FinalGatherOptions{16, 16});  // as bake's
  constexpr int kSeeds = 48;
  const Eigen::Vector3d centre(1.0 / 3, 1.0 / 3, 1.0 / 3);
  std::vector<double> ratios;
  for (int e = 0; e < mesh.elementCount(); e += 7) {
    // The luminance of the value over seeds: its spread, and the mean squared estimate.
    double sum = 0, squares = 0, estimate = 0;
    for (int s = 0; s < kSeeds; ++s) {
      RayCounts counts;
      Rng plain(streamKey(s, e, 7)), withError(streamKey(s, e, 7));
      const Rgb value = gather.outgoingRadiance(e, centre, plain, counts);
      Rgb standardError;
      const Rgb same = gather.outgoingRadiance(e, centre, withError, counts, standardError);
      for (int c = 0; c < 3; ++c) ASSERT_EQ(value[c], same[c]) << "the value is bit for bit";
      sum += value.g;
      squares += value.g * value.g;
      estimate += standardError.g * standardError.g;
    }
    const double spread = std::sqrt(std::max(0.0, squares - sum * sum / kSeeds) / (kSeeds - 1));
    if (!(spread > 1e-6 * std::fabs(sum / kSeeds))) continue;  // an emitter: nothing sampled
    ratios.push_back(std::sqrt(estimate / kSeeds) / spread);
  }
  ASSERT_GT(ratios.size(), 20u);
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  // The estimate treats the n-rooks samples as independent: at least the true error, not much
  // more. The spread of 48 seeds is itself known to about ±10%.
  EXPECT_GT(median, 0.8);
  EXPECT_LT(median, 1.6);
  size_t within = 0;
  for (double r : ratios) within += r > 0.5 && r < 2.0;
  EXPECT_GE(within, 0.8 * ratios.size()) << "median ratio " << median;
  std::printf("gather standard error / spread over seeds: median %.3f, %zu of %zu in (0.5, 2)\n",
              median, within, ratios.size());
}

TEST(LightmapConfidence, ExrErrorChannelBesideRgbReadsBackExactly) {
  ImageRgb image(5, 3);
  std::vector<float> error(15);
  for (int i = 0; i < 15; ++i) {
    image.pixels[i] = {0.1 * i, 1.0 / (i + 1), 1e3 * i};
    error[i] = 0.25f * static_cast<float>(i);
  }
  const std::string path =
      (std::filesystem::temp_directory_path() / "lightmap_confidence_test.exr").string();
  writeExr(path, image, {{"error", error}});
  const ImageRgb back = readExr(path);  // the RGB as from writeExr without the channel
  for (int i = 0; i < 15; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(back.pixels[i][c], static_cast<double>(static_cast<float>(image.pixels[i][c])));
  EXPECT_EQ(readExrChannel(path, "error"), error);
  EXPECT_THROW(readExrChannel(path, "confidence"), InputError);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace rad
