// `radiosity bake`'s confidence map end to end: lightmap.exr's "error" channel beside R, G, B
// (read back with OpenEXR, and readExr still reads the RGB), bake.json's "confidence" summary,
// the furnace's zero mesh error, and the gather's noise in the error channel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/output/image_io.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
using testing::runRadiosity;
using testing::scratchPath;

const std::string kData = RADIOSITY_DATA_DIR;

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return nlohmann::json::parse(s.str());
}

// The relative errors (error / luminance) of the lit texels of lightmap.exr, sorted.
std::vector<double> relativeErrors(const fs::path& dir) {
  const ImageRgb rgb = readExr((dir / "lightmap.exr").string());
  const std::vector<float> error = readExrChannel((dir / "lightmap.exr").string(), "error");
  EXPECT_EQ(error.size(), rgb.pixels.size());
  std::vector<double> relative;
  for (size_t i = 0; i < error.size(); ++i) {
    EXPECT_TRUE(std::isfinite(error[i]) && error[i] >= 0) << "texel " << i;
    if (rgb.pixels[i].isZero()) {
      EXPECT_EQ(error[i], 0.0f) << "an empty texel has nothing to be wrong about";
      continue;
    }
    relative.push_back(error[i] / rgb.pixels[i].luminance());
  }
  std::sort(relative.begin(), relative.end());
  return relative;
}

TEST(CliBakeConfidence, CornellErrorChannelAndSummary) {
  const fs::path dir = scratchPath("bake_confidence_cornell");
  const auto r = runRadiosity("bake " + kData + "/cornell_box/cornell_box.obj --out " +
                              dir.string() + " --elements 300 --rays 64 --lightmap-size 128");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  EXPECT_NE(r.stderrText.find("lightmap confidence: median relative error"), std::string::npos)
      << r.stderrText;
  const std::vector<double> relative = relativeErrors(dir);
  ASSERT_GT(relative.size(), 1000u);
  // The Cornell box's light varies over every wall: a coarse mesh shows some error somewhere.
  EXPECT_GT(relative.back(), 0.0);
  const auto confidence = readJson(dir / "bake.json").at("confidence");
  EXPECT_EQ(confidence.at("exr_channel"), "error");
  const double median = confidence.at("median_relative_error");
  const double p95 = confidence.at("p95_relative_error");
  const double above = confidence.at("fraction_above_10_percent");
  EXPECT_GT(confidence.at("texels").get<size_t>(), 0u);
  EXPECT_GT(median, 0.0);
  EXPECT_LE(median, p95);
  EXPECT_GE(above, 0.0);
  EXPECT_LE(above, 1.0);
  // The summary is over the covered texels, the file holds the dilated ones too: its median
  // agrees loosely with the summary's.
  const double fileMedian = relative[relative.size() / 2];
  EXPECT_GT(fileMedian, 0.5 * median);
  EXPECT_LT(fileMedian, 2.0 * median);
  EXPECT_NE(confidence.at("includes").get<std::string>().find("mesh"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CliBakeConfidence, FurnaceHasNoMeshErrorAndGatherNoiseShowsUp) {
  const fs::path plain = scratchPath("bake_confidence_furnace");
  const std::string common =
      " --solver gauss-seidel --tolerance 1e-8 --elements 300 --rays 64 "
      "--lightmap-size 64 --quiet";
  auto r =
      runRadiosity("bake " + kData + "/tests/furnace_box.obj --out " + plain.string() + common);
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  // L = 2 everywhere (Ke = 1, ρ = 0.5): nothing to interpolate wrong, the estimate is ~0.
  std::vector<double> relative = relativeErrors(plain);
  ASSERT_GT(relative.size(), 1000u);
  EXPECT_LT(relative.back(), 1e-5);
  // readExr reads the RGB of the file with its extra channel: the exact furnace value.
  for (const Rgb& p : readExr((plain / "lightmap.exr").string()).pixels) {
    if (p.isZero()) continue;
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(p[c], 2.0, 2e-5);
  }
  EXPECT_EQ(readJson(plain / "bake.json").at("confidence").at("fraction_above_10_percent"), 0.0);

  const fs::path gathered = scratchPath("bake_confidence_furnace_gather");
  r = runRadiosity("bake " + kData + "/tests/furnace_box.obj --out " + gathered.string() + common +
                   " --gather 16");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  relative = relativeErrors(gathered);
  ASSERT_GT(relative.size(), 1000u);
  // The gather's emitter samples vary (their MIS weights): a standard error above 0 on most
  // texels, and at 16 + 16 rays of at most some tens of per cent.
  EXPECT_GT(relative[relative.size() / 4], 1e-4);
  EXPECT_LT(relative[relative.size() / 2], 0.5);
  const auto confidence = readJson(gathered / "bake.json").at("confidence");
  EXPECT_NE(confidence.at("includes").get<std::string>().find("standard error"), std::string::npos);
  fs::remove_all(plain);
  fs::remove_all(gathered);
}

}  // namespace
}  // namespace rad
