// `radiosity bake --directional` end to end: the four L1 SH pages beside the lightmap, the same
// size, with their world axes as named (a floor under a lone sun: the L1 vector read back from
// lightmap_sh_L1x/L1y/L1z.exr points at the sun), the direction preview, bake.json's entry; and
// the option rules (no files when they are broken).
#include <gtest/gtest.h>

#include <Eigen/Core>
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

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A PNG's width and height from its IHDR chunk (big-endian at bytes 16 and 20).
std::pair<int, int> pngSize(const fs::path& p) {
  const std::string bytes = readText(p);
  if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
  auto at = [&](size_t o) {
    return int(uint8_t(bytes[o])) << 24 | int(uint8_t(bytes[o + 1])) << 16 |
           int(uint8_t(bytes[o + 2])) << 8 | int(uint8_t(bytes[o + 3]));
  };
  return {at(16), at(20)};
}

// A 2 × 2 floor facing +y, grey.
fs::path writeFloor(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "floor.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
  std::ofstream(dir / "floor.obj") << "mtllib floor.mtl\nusemtl grey\n"
                                      "v 0 0 0\nv 0 0 2\nv 2 0 2\nv 2 0 0\nf 1 2 3 4\n";
  return dir / "floor.obj";
}

// A floor under a sun travelling along (1, -2, 0.5): nothing else in the scene, so every filled
// texel's L1 vector (L1x, L1y, L1z) is E Y1-constant × the direction towards the sun, and L0 is
// E Y0. Also: each file is the lightmap's size, the preview too, bake.json lists them.
TEST(CliBakeDirectional, WritesTheFourShPagesWithTheirWorldAxes) {
  const fs::path dir = scratchPath("bake_directional");
  const fs::path scene = writeFloor(dir);
  const fs::path out = dir / "out";
  const auto r = runRadiosity("bake " + scene.string() + " --out " + out.string() +
                              " --sun 1 -2 0.5 3 2 1 --elements 50 --rays 64 --lightmap-size 32 "
                              "--directional --directional-rays 8 -q");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const ImageRgb main = readExr((out / "lightmap.exr").string());
  const ImageRgb l0 = readExr((out / "lightmap_sh_L0.exr").string());
  const ImageRgb lx = readExr((out / "lightmap_sh_L1x.exr").string());
  const ImageRgb ly = readExr((out / "lightmap_sh_L1y.exr").string());
  const ImageRgb lz = readExr((out / "lightmap_sh_L1z.exr").string());
  for (const ImageRgb* image : {&l0, &lx, &ly, &lz}) {
    EXPECT_EQ(image->width, main.width);
    EXPECT_EQ(image->height, main.height);
  }
  EXPECT_EQ(pngSize(out / "lightmap_direction.png"), std::make_pair(main.width, main.height));
  const Eigen::Vector3d toSun = -Eigen::Vector3d(1, -2, 0.5).normalized();
  const double y0 = 0.28209479177387814, y1 = 0.4886025119029199;
  const double e[3] = {3, 2, 1};
  size_t filled = 0;
  for (size_t i = 0; i < main.pixels.size(); ++i) {
    if (main.pixels[i].isZero()) {
      EXPECT_TRUE(l0.pixels[i].isZero());  // the same texels filled
      continue;
    }
    ++filled;
    for (int ch = 0; ch < 3; ++ch) {
      const Eigen::Vector3d v(lx.pixels[i][ch], ly.pixels[i][ch], lz.pixels[i][ch]);
      ASSERT_NEAR(l0.pixels[i][ch], e[ch] * y0, 1e-5 * e[ch]) << i;  // EXR floats
      ASSERT_NEAR((v - e[ch] * y1 * toSun).norm(), 0, 1e-5 * e[ch]) << i << " channel " << ch;
    }
  }
  EXPECT_GT(filled, main.pixels.size() / 4);
  const auto summary = nlohmann::json::parse(readText(out / "bake.json"));
  const auto& d = summary.at("directional");
  EXPECT_EQ(d.at("rays").get<int>(), 8);
  EXPECT_EQ(d.at("files").size(), 5u);
  for (const auto& f : d.at("files")) EXPECT_TRUE(fs::exists(out / f.get<std::string>())) << f;
  EXPECT_NE(d.at("convention").get<std::string>().find("+y up"), std::string::npos);
  fs::remove_all(dir);
}

// Several pages (the furnace box at 50 texels a unit: one face a 64² page, six pages): each
// page's four files carry its number (lightmap_P_sh_L0.exr, …, lightmap_P_direction.png), at its
// size. Every surface of the closed furnace has L = Ke / (1 − ρ) = 2, so every hemisphere ray
// sees 2: c0 = 2 · 2π Y0 exactly (to the solve's tolerance), and the L1 vector is 2 π Y1-constant
// along the face's inward normal (∫ ω dω over the hemisphere = π n), within 4σ of a plain Monte
// Carlo estimate with N rays (the normal component: Var cos θ = 1/12; a tangential one: 1/3).
TEST(CliBakeDirectional, EveryPageGetsItsOwnFurnaceShPages) {
  const fs::path dir = scratchPath("bake_directional_pages");
  const int rays = 32;
  const auto r = runRadiosity("bake " + kData + "/tests/furnace_box.obj --out " + dir.string() +
                              " --solver gauss-seidel --tolerance 1e-8 --elements 300 --rays 64 "
                              "--texel-density 50 --lightmap-size 64 --directional "
                              "--directional-rays " +
                              std::to_string(rays) + " --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  const int pages =
      nlohmann::json::parse(readText(dir / "bake.json"))["lightmap"]["pages"].get<int>();
  ASSERT_EQ(pages, 6);
  EXPECT_FALSE(fs::exists(dir / "lightmap_sh_L0.exr"));
  EXPECT_FALSE(fs::exists(dir / ("lightmap_" + std::to_string(pages) + "_sh_L0.exr")));
  const double y0 = 0.28209479177387814, y1 = 0.4886025119029199;
  const double spread = 2 * 2 * M_PI * y1 / std::sqrt(rays);  // 2π L Y1-constant / √N
  for (int p = 0; p < pages; ++p) {
    const std::string stem = "lightmap_" + std::to_string(p);
    const ImageRgb main = readExr((dir / (stem + ".exr")).string());
    const ImageRgb l0 = readExr((dir / (stem + "_sh_L0.exr")).string());
    const ImageRgb lx = readExr((dir / (stem + "_sh_L1x.exr")).string());
    const ImageRgb ly = readExr((dir / (stem + "_sh_L1y.exr")).string());
    const ImageRgb lz = readExr((dir / (stem + "_sh_L1z.exr")).string());
    EXPECT_EQ(pngSize(dir / (stem + "_direction.png")), std::make_pair(main.width, main.height));
    size_t filled = 0;
    for (size_t i = 0; i < main.pixels.size(); ++i) {
      if (main.pixels[i].isZero()) continue;
      ++filled;
      ASSERT_NEAR(l0.pixels[i].g, 2 * 2 * M_PI * y0, 1e-4) << stem << " texel " << i;
      const Eigen::Vector3d v(lx.pixels[i].g, ly.pixels[i].g, lz.pixels[i].g);
      int axis;
      v.cwiseAbs().maxCoeff(&axis);
      for (int a = 0; a < 3; ++a)
        if (a == axis)
          ASSERT_NEAR(std::abs(v[a]), 2 * M_PI * y1, 4 * spread * std::sqrt(1 / 12.0))
              << stem << " texel " << i;
        else
          ASSERT_NEAR(v[a], 0, 4 * spread * std::sqrt(1 / 3.0)) << stem << " texel " << i;
    }
    EXPECT_GT(filled, 2000u) << stem;  // 50² texels of one face
  }
  fs::remove_all(dir);
}

// Without --directional the bake writes none of them.
TEST(CliBakeDirectional, OffByDefault) {
  const fs::path dir = scratchPath("bake_directional_off");
  const fs::path scene = writeFloor(dir);
  const fs::path out = dir / "out";
  const auto r =
      runRadiosity("bake " + scene.string() + " --out " + out.string() +
                   " --sun 1 -2 0.5 3 2 1 --elements 50 --rays 64 --lightmap-size 32 -q");
  ASSERT_EQ(r.exitCode, 0) << r.stderrText;
  EXPECT_TRUE(fs::exists(out / "lightmap.exr"));
  EXPECT_FALSE(fs::exists(out / "lightmap_sh_L0.exr"));
  EXPECT_FALSE(fs::exists(out / "lightmap_direction.png"));
  EXPECT_FALSE(nlohmann::json::parse(readText(out / "bake.json")).contains("directional"));
  fs::remove_all(dir);
}

// --directional-rays without --directional, --directional with --no-lightmap or --light-groups:
// bad input (exit 1), a message naming the option, and nothing written.
TEST(CliBakeDirectional, BrokenOptionRulesFailAndWriteNothing) {
  const fs::path dir = scratchPath("bake_directional_bad");
  const fs::path scene = writeFloor(dir);
  const fs::path out = dir / "out";
  const std::string base = "bake " + scene.string() + " --out " + out.string() +
                           " --sun 1 -2 0.5 3 2 1 --elements 50 --rays 16 --lightmap-size 32 ";
  struct Case {
    std::string options, message;
  };
  for (const Case& c : {Case{"--directional-rays 8", "add --directional"},
                        Case{"--directional --no-lightmap", "--no-lightmap"},
                        Case{"--directional --light-groups", "--light-groups"}}) {
    const auto r = runRadiosity(base + c.options);
    EXPECT_EQ(r.exitCode, 1) << c.options << "\n" << r.stderrText;
    EXPECT_NE(r.stderrText.find(c.message), std::string::npos) << c.options << ": " << r.stderrText;
    EXPECT_FALSE(fs::exists(out)) << c.options;
  }
  const auto r = runRadiosity(base + "--directional --directional-rays 0");
  EXPECT_EQ(r.exitCode, 2) << r.stderrText;  // out of the option's range: a usage error
  EXPECT_NE(r.stderrText.find("--directional-rays"), std::string::npos) << r.stderrText;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
