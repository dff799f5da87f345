// The bake module (radiosity/bake): bakeSolution on solved scenes, tested without the binary.
// The texels against analytic values in the furnace, the layout's geometry, the report's
// counts, and the light groups' layers against the whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "radiosity/bake/bake_solution.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/scene_loader.h"

namespace rad {
namespace {

const std::string kData = RADIOSITY_DATA_DIR;

// data/tests/furnace_box.obj: a closed unit cube, every face emitting Ke = 1 and reflecting
// ρ = 0.5 (grey).
constexpr double kKe = 1, kRho = 0.5;
constexpr int kBounces = 12;

// The furnace solved by exactly kBounces Jacobi bounces from B_0 = E. Every hemisphere ray of a
// closed box hits it, so each row of F sums to 1 and every iterate is uniform:
// B_K = E Σ_{j≤K} ρ^j with E = π Ke (REFERENCES.md's furnace, truncated after K bounces).
SolveResult solvedFurnace(int elements) {
  SolveOptions options;
  options.scenePath = kData + "/tests/furnace_box.obj";
  options.targetElements = elements;
  options.raysPerElement = 32;
  options.solver = SolverKind::Jacobi;
  options.bounces = kBounces;
  options.threads = 2;
  return solveScene(loadScene(options.scenePath, options.lights), options);
}

// Σ_{j=from..K} ρ^j.
double bounceSum(int from) {
  double sum = 0;
  for (int j = from; j <= kBounces; ++j) sum += std::pow(kRho, j);
  return sum;
}

BakeSpec smallSpec() {
  BakeSpec spec;
  spec.layout.lightmapSize = 64;
  spec.dilation = spec.layout.padding;
  return spec;
}

// Every texel an element or its dilation fills holds the furnace's radiance B_K/π = Ke Σ ρ^j: the
// interpolation of equal vertex values is that value, and the dilation's means of equal
// neighbours too. The only error is double rounding (a few ulps over sums of a few terms), so
// 1e-12 relative. Empty texels hold 0. Irradiance content: H/π = (B − E)/(π ρ) = Ke Σ_{j≥1}
// ρ^(j−1), exactly as well.
TEST(BakeSolution, FurnaceTexelsHoldTheAnalyticRadianceAndIrradiance) {
  const SolveResult solved = solvedFurnace(200);
  for (const LightmapContent content : {LightmapContent::Radiance, LightmapContent::Irradiance}) {
    BakeSpec spec = smallSpec();
    spec.content = content;
    const BakeResult baked = bakeSolution(solved, SolveOptions(), spec);
    const double exact =
        content == LightmapContent::Radiance ? kKe * bounceSum(0) : kKe * bounceSum(1) / kRho;
    ASSERT_EQ(baked.lightmaps.size(), 1u);
    size_t filled = 0;
    for (const Lightmap& page : baked.lightmaps)
      for (size_t t = 0; t < page.state.size(); ++t)
        for (int c = 0; c < 3; ++c) {
          const double v = page.radiance.pixels[t][c];
          if (page.state[t] == TexelState::Empty) {
            ASSERT_EQ(v, 0) << t;
          } else {
            ASSERT_NEAR(v, exact, 1e-12 * exact) << t << " " << lightmapContentName(content);
            filled += c == 0;
          }
        }
    EXPECT_GT(filled, 0u);
    // The vertex colours show the same radiance.
    for (const Rgb& v : baked.vertexRadiance)
      EXPECT_NEAR(v[0], kKe * bounceSum(0), 1e-12 * kKe * bounceSum(0));
  }
}

// The per-texel gather in the furnace: a texel's value is Ke + ρ (direct + gathered), the direct
// light Ke from every direction (every face emits; the box is convex, so every emitter point
// is seen) and the gathered light (B_K − E)/π = Ke Σ_{j=1..K} ρ^j from the solution, so its
// expectation is Ke Σ_{j=0..K+1} ρ^j: one bounce past the solve's. The texels draw independent
// streams, so the mean of N covered texels has the standard error √(Σ σ_t²)/N from the gather's
// own per-texel σ_t; the mean lies within 5 of those (a chance of about 6e-7 for a normal mean).
TEST(BakeSolution, FurnaceGatherIsUnbiasedWithinItsStandardError) {
  const SolveResult solved = solvedFurnace(200);
  BakeSpec spec = smallSpec();
  spec.gather = {16, 0};
  const BakeResult baked = bakeSolution(solved, SolveOptions(), spec);
  const double exact = kKe * (bounceSum(0) + std::pow(kRho, kBounces + 1));
  double sum = 0, variance = 0;
  size_t n = 0;
  for (int page = 0; page < baked.layout.pages; ++page)
    for (size_t t = 0; t < baked.lightmaps[page].state.size(); ++t) {
      if (baked.lightmaps[page].state[t] != TexelState::Covered) continue;
      sum += baked.lightmaps[page].radiance.pixels[t][0];
      // The error pages hold the gather's standard error (grey here: luminance = channel).
      const double sigma = baked.errorPages[page].radiance.pixels[t][0];
      variance += sigma * sigma;
      ++n;
    }
  ASSERT_GT(n, 100u);
  ASSERT_GT(variance, 0);
  const double mean = sum / n, standardError = std::sqrt(variance) / n;
  EXPECT_NEAR(mean, exact, 5 * standardError) << "standard error " << standardError;
  EXPECT_LT(5 * standardError, 0.01 * exact);  // so a bias of 1% would show
}

// The report's counts: the texels by state make up the pages, the confidence summary covers the
// covered texels (all lit in the furnace), and the mesh's displayed error of a uniform field is 0
// (up to rounding: relative 1e-9). bake.json carries the same numbers.
TEST(BakeSolution, ReportCountsTheTexelsAndTheFurnacesConfidence) {
  const SolveResult solved = solvedFurnace(200);
  const BakeResult baked = bakeSolution(solved, SolveOptions(), smallSpec());
  const BakeReport& report = baked.report;
  ASSERT_TRUE(report.lightmap && report.confidence);
  const BakeReport::LightmapFacts& l = *report.lightmap;
  EXPECT_EQ(l.pages, baked.layout.pages);
  EXPECT_EQ(l.charts, baked.layout.rects.size());
  EXPECT_EQ(l.covered + l.conservative + l.dilated + l.empty,
            static_cast<size_t>(l.pages) * l.width * l.height);
  EXPECT_GT(l.covered, 0u);
  EXPECT_EQ(report.confidence->summary.texels, l.covered);
  EXPECT_LT(report.confidence->summary.p95Relative, 1e-9);
  for (const Lightmap& page : baked.errorPages)
    for (const Rgb& e : page.radiance.pixels) EXPECT_LT(e.maxComponent(), 1e-9);
  EXPECT_EQ(report.elements, solved.solution.mesh->elementCount());
  const nlohmann::json json = bakeJson(report);
  EXPECT_EQ(json["lightmap"]["texels_covered"], l.covered);
  EXPECT_EQ(json["confidence"]["texels"], l.covered);
  EXPECT_FALSE(json.contains("light_groups"));
}

// A texel whose centre lies in the charts' geometry is inside its chart's rectangle, that
// rectangle inside its page, and no two rectangles of one page overlap; the pages counted are the
// pages the charts use. On the Cornell box at a density that needs several 128² pages.
TEST(BakeSolution, ChartsLieInsideTheirPagesWithoutOverlap) {
  SolveOptions options;
  options.scenePath = kData + "/cornell_box/cornell_box.obj";
  options.targetElements = 300;
  options.raysPerElement = 16;
  options.threads = 2;
  const SolveResult solved = solveScene(loadScene(options.scenePath, options.lights), options);
  BakeSpec spec;
  spec.layout.texelDensity = 200;
  spec.layout.lightmapSize = 128;
  spec.dilation = spec.layout.padding;
  const BakeResult baked = bakeSolution(solved, options, spec);
  const LightmapLayout& layout = baked.layout;
  ASSERT_GT(layout.pages, 1);
  EXPECT_EQ(baked.lightmaps.size(), static_cast<size_t>(layout.pages));
  EXPECT_EQ(baked.errorPages.size(), static_cast<size_t>(layout.pages));
  int lastPage = 0;
  for (size_t i = 0; i < layout.rects.size(); ++i) {
    const ChartRect& a = layout.rects[i];
    lastPage = std::max(lastPage, a.page);
    EXPECT_GE(a.x, 0);
    EXPECT_GE(a.y, 0);
    EXPECT_LE(a.x + a.width, layout.width) << i;
    EXPECT_LE(a.y + a.height, layout.height) << i;
    for (size_t j = i + 1; j < layout.rects.size(); ++j) {
      const ChartRect& b = layout.rects[j];
      const bool apart = a.page != b.page || a.x + a.width <= b.x || b.x + b.width <= a.x ||
                         a.y + a.height <= b.y || b.y + b.height <= a.y;
      EXPECT_TRUE(apart) << i << " " << j;
    }
  }
  EXPECT_EQ(lastPage + 1, layout.pages);
  for (size_t e = 0; e < layout.texels.size(); ++e) {
    const ChartRect& r = layout.rects[layout.chartOfElement[e]];
    for (const Eigen::Vector2d& corner : layout.texels[e]) {
      EXPECT_GE(corner.x(), r.x + layout.padding - 1e-9) << e;
      EXPECT_LE(corner.x(), r.x + r.width - layout.padding + 1e-9) << e;
      EXPECT_GE(corner.y(), r.y + layout.padding - 1e-9) << e;
      EXPECT_LE(corner.y(), r.y + r.height - layout.padding + 1e-9) << e;
    }
  }
  // Each texel an element owns is on that element's page.
  for (int page = 0; page < layout.pages; ++page)
    for (int element : baked.lightmaps[page].element) {
      if (element >= 0) {
        ASSERT_EQ(layout.page(element), page);
      }
    }
  EXPECT_EQ(baked.report.lightmap->pages, layout.pages);
}

// The layers' pages and vertex values against the whole's, and the report's groups.
void expectLayersSumToTheWhole(const BakeResult& baked) {
  ASSERT_EQ(baked.layerLightmaps.size(), 3u);
  ASSERT_EQ(baked.report.lightGroups.size(), 3u);
  EXPECT_EQ(baked.report.lightGroups[1].group.name, "lamp");
  for (int page = 0; page < baked.layout.pages; ++page) {
    const Lightmap& whole = baked.lightmaps[page];
    double brightest = 0;
    for (const Rgb& v : whole.radiance.pixels) brightest = std::max(brightest, v.maxComponent());
    ASSERT_GT(brightest, 0);
    for (size_t t = 0; t < whole.radiance.pixels.size(); ++t) {
      Rgb sum;
      for (const auto& layer : baked.layerLightmaps) sum = sum + layer[page].radiance.pixels[t];
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(sum[c], whole.radiance.pixels[t][c], 1e-9 * brightest) << t;
    }
  }
  for (size_t v = 0; v < baked.vertexRadiance.size(); ++v) {
    Rgb sum;
    for (const auto& layer : baked.layerVertexRadiance) sum = sum + layer[v];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sum[c], baked.vertexRadiance[v][c], 1e-9 * (1 + baked.vertexRadiance[v][c]));
  }
  const nlohmann::json json = bakeJson(baked.report);
  ASSERT_EQ(json["light_groups"].size(), 3u);
  EXPECT_EQ(json["light_groups"][1]["files"][0], "group_lamp_vertex_colors.ply");
}

// --light-groups: the Cornell box's ceiling light and the two lamps of two_lamps.lights.json are
// three layers; the solution is linear in the emission, each texel is linear in B and Le, so the
// layers' texels sum to the whole's (to double rounding over three terms: 1e-9 relative to the
// page's brightest texel), as do their vertex values. The report names the groups.
TEST(BakeSolution, LightGroupLayersSumToTheWhole) {
  SolveOptions options;
  options.scenePath = kData + "/cornell_box/cornell_box.obj";
  options.lights.file = kData + "/cornell_box/two_lamps.lights.json";
  options.lightGroups = true;
  options.targetElements = 300;
  options.raysPerElement = 16;
  options.threads = 2;
  const SolveResult solved = solveScene(loadScene(options.scenePath, options.lights), options);
  // Irradiance content too: there each layer's texels subtract its own emitters' Le alone.
  for (const LightmapContent content : {LightmapContent::Radiance, LightmapContent::Irradiance}) {
    BakeSpec spec = smallSpec();
    spec.content = content;
    expectLayersSumToTheWhole(bakeSolution(solved, options, spec));
  }
}

// Without a lightmap: the vertex colours alone, and the report says what was skipped.
TEST(BakeSolution, VertexColoursOnlySkipsTheLightmap) {
  const SolveResult solved = solvedFurnace(50);
  BakeSpec spec = smallSpec();
  spec.lightmap = false;
  const BakeResult baked = bakeSolution(solved, SolveOptions(), spec);
  EXPECT_TRUE(baked.lightmaps.empty());
  EXPECT_FALSE(baked.report.lightmap.has_value());
  ASSERT_EQ(baked.report.skipped.size(), 1u);
  EXPECT_EQ(baked.vertexRadiance.size(), static_cast<size_t>(baked.interpolation.vertexCount()));
}

}  // namespace
}  // namespace rad
