// `radiosity view --screenshot` under Xvfb: the Cornell box from its camera, walls on the right
// sides, the convergence panel, and the light probes' spheres.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.h"

namespace rad {
namespace {

namespace fs = std::filesystem;
const std::string cornellDir = std::string(RADIOSITY_DATA_DIR) + "/cornell_box";

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

// Runs `radiosity view ...` under xvfb-run; returns the exit code, stderr in `errors`.
int runView(const std::string& arguments, std::string& errors) {
  const fs::path err = testing::scratchPath("view_stderr.txt");
  const std::string command = "xvfb-run -a " + std::string(RADIOSITY_BINARY) + " view " +
                              arguments + " >/dev/null 2>" + err.string() + " </dev/null";
  const int status = std::system(command.c_str());
  std::ifstream in(err);
  errors.assign(std::istreambuf_iterator<char>(in), {});
  fs::remove(err);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;  // -1: killed by a signal, never expected
}

struct Image {
  int width = 0, height = 0;
  std::vector<std::array<int, 3>> rgb;  // row 0 at the top
  std::array<int, 3> at(double fx, double fy) const {
    return rgb[static_cast<int>(fy * (height - 1)) * width + static_cast<int>(fx * (width - 1))];
  }
  // Mean colour of the box [fx0, fx1] × [fy0, fy1] (fractions of the image, y down).
  std::array<double, 3> mean(double fx0, double fx1, double fy0, double fy1) const {
    std::array<double, 3> sum{};
    int n = 0;
    for (int y = static_cast<int>(fy0 * height); y < static_cast<int>(fy1 * height); ++y)
      for (int x = static_cast<int>(fx0 * width); x < static_cast<int>(fx1 * width); ++x, ++n)
        for (int c = 0; c < 3; ++c) sum[c] += rgb[y * width + x][c];
    for (double& s : sum) s /= std::max(n, 1);
    return sum;
  }
};

Image readPng(const fs::path& path) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Image out;
  int dims[3];
  image->GetDimensions(dims);
  out.width = dims[0], out.height = dims[1];
  out.rgb.resize(static_cast<size_t>(out.width) * out.height);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)  // VTK images start at the bottom row
        out.rgb[(out.height - 1 - y) * out.width + x][c] =
            static_cast<int>(image->GetScalarComponentAsDouble(x, y, 0, c));
  return out;
}

// A copy of the Cornell box with the camera sidecar of REFERENCES.md (metres).
fs::path cornellWithCamera(const std::string& name) {
  const fs::path dir = testing::scratchPath(name);
  fs::create_directories(dir);
  fs::copy_file(cornellDir + "/cornell_box.obj", dir / "cornell_box.obj");
  fs::copy_file(cornellDir + "/cornell_box.mtl", dir / "cornell_box.mtl");
  std::ofstream(dir / "cornell_box.camera.json")
      << R"({"position": [0.278, 0.273, -0.8], "look_at": [0.278, 0.273, 0.0], "up": [0, 1, 0],
            "vfov_degrees": 39.3, "width": 320, "height": 240,
            "comment": "the one camera reader: unknown keys are errors, width and height required"})";
  return dir;
}

TEST(ViewScreenshot, CornellBoxFromItsCameraHasRedLeftGreenRight) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_cornell");
  const fs::path png = dir / "shot.png";
  std::string errors;
  ASSERT_EQ(runView((dir / "cornell_box.obj").string() + " --elements 300 --rays 64 --screenshot " +
                        png.string() + " --size 320x240 --camera-from-scene --no-chart --quiet",
                    errors),
            0)
      << errors;
  const Image image = readPng(png);
  ASSERT_EQ(image.width, 320);
  ASSERT_EQ(image.height, 240);
  // Only the PNG: the temporary name was renamed away.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.path().extension() == ".png";
  EXPECT_EQ(files, 1);

  // From (0.278, 0.273, -0.8) looking +z with +y up, +x is to the left. The scene is the left
  // 240 px (the scalar bar's strip takes the right 80), square, so the 39.3° frame spans its
  // width: the red wall (x = 0.556) covers about 1-15% of the image's width at mid height, the
  // green wall (x = 0) about 59-74%.
  const auto red = image.mean(0.04, 0.12, 0.4, 0.6);
  EXPECT_GT(red[0], 2 * red[1]) << "left wall is not red";
  EXPECT_GT(red[0], 2 * red[2]) << "left wall is not red";
  const auto green = image.mean(0.62, 0.70, 0.4, 0.6);
  EXPECT_GT(green[1], 1.3 * green[0]) << "right wall is not green";
  EXPECT_GT(green[1], 1.3 * green[2]) << "right wall is not green";

  // Most of the frame is the box, not the background (the strip's top-right corner).
  const auto background = image.at(1.0, 0.0);
  int scene = 0;
  for (const auto& p : image.rgb)
    scene += std::abs(p[0] - background[0]) + std::abs(p[1] - background[1]) +
                 std::abs(p[2] - background[2]) >
             6;
  EXPECT_GT(scene, static_cast<int>(image.rgb.size() / 2));
  fs::remove_all(dir);
}

// A small window keeps the scene in view: no convergence panel over the green wall (below 640 px
// wide the panel is hidden) and the scalar bar in a strip of its own, off the walls. Before the
// layout rule the panel took the right 36% of a 400 px window and the bar sat on the green wall.
TEST(ViewScreenshot, SmallWindowShowsTheGreenWallClearOfPanelAndBar) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_small");
  const fs::path png = dir / "small.png";
  std::string errors;
  ASSERT_EQ(runView((dir / "cornell_box.obj").string() + " --elements 300 --rays 64 --screenshot " +
                        png.string() + " --size 400x400 --camera-from-scene --quiet",
                    errors),
            0)
      << errors;
  const Image image = readPng(png);
  ASSERT_EQ(image.width, 400);
  ASSERT_EQ(image.height, 400);
  // The scene takes the left 290 px (the bar's strip the next 110), its camera angle spanning
  // the width: the green wall covers about x 240-290, y 100-330 (checked on the image).
  for (const double x0 : {0.62, 0.66}) {
    const auto green = image.mean(x0, x0 + 0.04, 0.35, 0.65);
    EXPECT_GT(green[1], 1.3 * green[0]) << "no green wall at x " << x0;
    EXPECT_GT(green[1], 1.3 * green[2]) << "no green wall at x " << x0;
  }
  // And the red wall on the left, as in the large window.
  const auto red = image.mean(0.04, 0.1, 0.35, 0.65);
  EXPECT_GT(red[0], 2 * red[1]) << "left wall is not red";
  EXPECT_GT(red[0], 2 * red[2]) << "left wall is not red";
  fs::remove_all(dir);
}

TEST(ViewScreenshot, ConvergencePanelAndSavedSolution) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_panel");
  std::string errors;
  const fs::path withChart = dir / "chart.png";
  ASSERT_EQ(runView((dir / "cornell_box.obj").string() +
                        " --elements 200 --rays 32 --edges --outlines --rays-of 5"
                        " --camera-from-scene --screenshot " +
                        withChart.string() + " --size 1280x720 --quiet",
                    errors),
            0)
      << errors;
  const Image image = readPng(withChart);
  ASSERT_EQ(image.width, 1280);
  ASSERT_EQ(image.height, 720);
  // At the default size the panel (right 36%) is shown: a white background with the curve and
  // axes drawn on it.
  const int panel = static_cast<int>(0.645 * image.width);
  int white = 0, ink = 0, total = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = panel; x < image.width; ++x, ++total) {
      const auto& p = image.rgb[y * image.width + x];
      white += p[0] > 245 && p[1] > 245 && p[2] > 245;
      ink += p[0] < 200 || p[1] < 200 || p[2] < 200;
    }
  EXPECT_GT(white, total / 2);
  EXPECT_GT(ink, 50);
  // Its title (the top 30 rows) is drawn and not cut: no ink in the 4 columns at either edge.
  int title = 0, edge = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = panel; x < image.width; ++x) {
      const auto& p = image.rgb[y * image.width + x];
      const bool dark = p[0] < 160 && p[1] < 160 && p[2] < 160;
      title += dark;
      edge += dark && (x < panel + 4 || x >= image.width - 4);
    }
  EXPECT_GT(title, 100);
  EXPECT_EQ(edge, 0);
  // The scalar bar's strip (110 px left of the panel) leaves the green wall, 0.44-0.545 of the
  // width from the scene camera, uncovered up to its inner edge.
  const auto green = image.mean(0.5, 0.54, 0.3, 0.7);
  EXPECT_GT(green[1], 1.3 * green[0]) << "right wall is not green next to the bar";
  EXPECT_GT(green[1], 1.3 * green[2]) << "right wall is not green next to the bar";

  // A saved solution opens from its directory.
  const fs::path out = dir / "out";
  const auto solve =
      testing::runRadiosity("solve " + (dir / "cornell_box.obj").string() +
                            " --elements 200 --rays 32 --quiet --out " + out.string());
  ASSERT_EQ(solve.exitCode, 0) << solve.stderrText;
  const fs::path saved = dir / "saved.png";
  ASSERT_EQ(runView(out.string() + " --camera-from-scene --screenshot " + saved.string() +
                        " --size 200x150 --quiet",
                    errors),
            0)
      << errors;
  EXPECT_EQ(readPng(saved).width, 200);
  fs::remove_all(dir);
}

TEST(ViewScreenshot, SteppedSolverBrightensTowardsTheSolution) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_steps");
  // Shooting only ever adds light: the back wall (centre of the image) is black at B = E, brighter
  // after some shots and brightest once converged, under the same fixed exposure.
  double previous = -100;
  for (const std::string stop : {"--stop-after 0", "--stop-after 20", ""}) {
    const fs::path png = dir / "steps.png";
    std::string errors;
    ASSERT_EQ(runView((dir / "cornell_box.obj").string() +
                          " --elements 300 --rays 64 --camera-from-scene --no-chart " + stop +
                          " --screenshot " + png.string() + " --size 200x150 --quiet",
                      errors),
              0)
        << errors;
    const auto wall = readPng(png).mean(0.42, 0.58, 0.35, 0.5);
    const double brightness = wall[0] + wall[1] + wall[2];
    if (stop == "--stop-after 0") {
      EXPECT_LT(brightness, 3.0) << "walls must be black before the first shot";
    }
    EXPECT_GT(brightness, previous + 10) << stop;
    previous = brightness;
  }
  fs::remove_all(dir);
}

// A hierarchical solve: --rays-of draws the element's links, yellow to surfaces and cyan to
// clusters (dimmed by the light each brings), and the log counts them. The same view without it
// (the same solve: deterministic) differs only where lines are drawn, and there in their colours.
TEST(ViewScreenshot, HierarchicalSolveDrawsAPickedElementsLinks) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_links");
  const std::string common = (dir / "cornell_box.obj").string() +
                             " --solver hierarchical --elements 300 --rays 64 --camera-from-scene"
                             " --size 320x240 --screenshot ";
  std::string errors;
  const fs::path plain = dir / "plain.png", links = dir / "links.png";
  ASSERT_EQ(runView(common + plain.string(), errors), 0) << errors;
  // Element 0 is on the floor: its links reach up to the ceiling's lamp and the walls.
  ASSERT_EQ(runView(common + links.string() + " --rays-of 0", errors), 0) << errors;
  EXPECT_NE(errors.find("element 0: "), std::string::npos) << errors;
  EXPECT_NE(errors.find(" links, "), std::string::npos) << errors;
  const Image a = readPng(plain), b = readPng(links);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  int changed = 0, lineColoured = 0;
  for (size_t k = 0; k < a.rgb.size(); ++k) {
    const auto &p = a.rgb[k], &q = b.rgb[k];
    if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) < 30) continue;
    ++changed;
    // Yellow: blue the smallest by far; cyan: red the smallest by far.
    lineColoured += (q[2] < q[0] / 2 && q[2] < q[1] / 2) || (q[0] < q[1] / 2 && q[0] < q[2] / 2);
  }
  EXPECT_GT(changed, 200) << "no links drawn";
  EXPECT_GT(lineColoured, changed * 3 / 4) << "what changed is not the links' colours";
  fs::remove_all(dir);
}

// The files on which VTK 9.1's XML reader crashed (fuzzer findings, kept in the corpus): `view`
// refuses each with exit code 1 naming the file and line, instead of dying with SIGSEGV.
TEST(ViewScreenshot, FilesThatCrashedVtksReaderAreRefused) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const std::string corpus =
      std::string(RADIOSITY_DATA_DIR) + "/../tests/fuzz/corpus/solution_vtp/";
  const fs::path dir = testing::scratchPath("view_vtk_crash");
  fs::create_directories(dir);
  for (const char* name :
       {"regression_vtk_string_array_ascii.vtp", "regression_vtk_string_array_binary.vtp"}) {
    fs::copy_file(corpus + name, dir / "solution.vtp", fs::copy_options::overwrite_existing);
    std::string errors;
    const fs::path png = dir / "never.png";
    EXPECT_EQ(runView(dir.string() + " --screenshot " + png.string(), errors), 1) << name;
    EXPECT_NE(errors.find((dir / "solution.vtp").string() + ":"), std::string::npos)
        << name << ": " << errors;
    EXPECT_FALSE(fs::exists(png)) << name;
  }
  fs::remove_all(dir);
}

TEST(ViewScreenshot, BadInputNamesTheFileAndLeavesNoPng) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = testing::scratchPath("view_bad");
  fs::create_directories(dir);
  std::string errors;
  const fs::path png = dir / "never.png";
  EXPECT_EQ(runView(dir.string() + " --screenshot " + png.string(), errors), 1);
  EXPECT_NE(errors.find((dir / "solution.vtp").string()), std::string::npos) << errors;
  std::ofstream(dir / "cornell_box.camera.json") << "{\"position\": [0, 0, 1],\n \"look_at\": ";
  fs::copy_file(cornellDir + "/cornell_box.obj", dir / "cornell_box.obj");
  fs::copy_file(cornellDir + "/cornell_box.mtl", dir / "cornell_box.mtl");
  EXPECT_EQ(runView((dir / "cornell_box.obj").string() +
                        " --elements 100 --rays 16 --camera-from-scene --no-chart "
                        "--screenshot " +
                        png.string(),
                    errors),
            1);
  EXPECT_NE(errors.find("cornell_box.camera.json"), std::string::npos) << errors;
  EXPECT_EQ(runView((dir / "cornell_box.obj").string() + " --size 12x --screenshot " + png.string(),
                    errors),
            1);
  EXPECT_NE(errors.find("--size"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(png));
  fs::remove_all(dir);
}

// `view DIR` shows DIR/probes.bin: each front probe of the Cornell box's 3 × 3 × 3 grid is a
// sphere where the scene camera projects it (gone with --no-probes), and its shading follows its
// SH: of two points above and below (left and right of) its centre, the brighter on screen is the
// one whose normal the probe's irradiance (probes.json) says gets more light. (From the camera a
// front probe shows the half that faces the box's open front, not its top: the lamp-lit tops are
// checked in ProbePolyData.ProbeLitFromAboveIsBrighterOnTop.) A truncated probes.bin is refused
// naming it; --no-probes does not read it.
TEST(ViewScreenshot, LightProbesAreSpheresShadedByTheirSh) {
  if (!haveXvfb())
    GTEST_SKIP() << "xvfb-run is not installed: cannot render off-screen with Debian's VTK";
  const fs::path dir = cornellWithCamera("view_probes");
  const fs::path out = dir / "out";
  const auto solve = testing::runRadiosity(
      "solve " + (dir / "cornell_box.obj").string() +
      " --elements 300 --rays 64 --probes 0.2 --probe-rays 256 --quiet --out " + out.string());
  ASSERT_EQ(solve.exitCode, 0) << solve.stderrText;
  std::string errors;
  const fs::path with = dir / "with.png", without = dir / "without.png";
  const std::string common = out.string() + " --camera-from-scene --size 320x240 --quiet";
  ASSERT_EQ(runView(common + " --screenshot " + with.string(), errors), 0) << errors;
  ASSERT_EQ(runView(common + " --no-probes --screenshot " + without.string(), errors), 0) << errors;
  const Image a = readPng(with), b = readPng(without);
  ASSERT_EQ(a.width, 320);
  ASSERT_EQ(b.width, 320);

  // The front row of probes (smallest z), projected by the scene camera: at (0.278, 0.273, -0.8)
  // looking +z, +y up, +x to the left, 39.3° over the scene's 240 × 240 px.
  std::ifstream json(out / "probes.json");
  const nlohmann::json probes = nlohmann::json::parse(json).at("probes");
  ASSERT_EQ(probes.size(), 27u);
  double front = 1e9;
  for (const auto& p : probes) front = std::min(front, p.at("position")[2].get<double>());
  const Eigen::Vector3d eye(0.278, 0.273, -0.8);
  const double focal = 120 / std::tan(39.3 / 2 * M_PI / 180), radius = 0.15 * 0.2;
  auto grey = [](const Image& image, int x, int y) {
    const auto& p = image.rgb[y * image.width + x];
    return p[0] + p[1] + p[2];
  };
  int checked = 0, decisive = 0, agree = 0;
  for (const auto& p : probes) {
    const auto& x = p.at("position");
    const Eigen::Vector3d centre(x[0].get<double>(), x[1].get<double>(), x[2].get<double>());
    if (std::abs(centre.z() - front) > 1e-6 || p.at("inside").get<bool>()) continue;
    const double depth = centre.z() - eye.z();
    const double u = 120 - focal * (centre.x() - eye.x()) / depth;
    const double v = 120 - focal * (centre.y() - eye.y()) / depth;
    const double r = focal * radius / depth;
    ASSERT_GT(r, 8);
    // The irradiance's channel sum the SH gives (docs/rendering.md's convention, written out
    // here) at the sphere's normal under pixel (px, py): the camera ray meets the sphere there.
    auto expected = [&](int px, int py) {
      const Eigen::Vector3d d =
          Eigen::Vector3d(-(px + 0.5 - 120) / focal, -(py + 0.5 - 120) / focal, 1).normalized();
      const Eigen::Vector3d m = eye - centre;
      const double bq = m.dot(d), disc = bq * bq - (m.squaredNorm() - radius * radius);
      if (disc < 0) return -1.0;
      const Eigen::Vector3d n = (m + (-bq - std::sqrt(disc)) * d) / radius;
      const double y[9] = {0.282095,
                           0.488603 * n.y(),
                           0.488603 * n.z(),
                           0.488603 * n.x(),
                           1.092548 * n.x() * n.y(),
                           1.092548 * n.y() * n.z(),
                           0.315392 * (3 * n.z() * n.z() - 1),
                           1.092548 * n.x() * n.z(),
                           0.546274 * (n.x() * n.x() - n.y() * n.y())};
      double e = 0;
      for (int k = 0; k < 9; ++k) {
        const double band = k == 0 ? M_PI : k < 4 ? 2 * M_PI / 3 : M_PI / 4;
        for (int c = 0; c < 3; ++c) e += band * p.at("sh")[k][c].get<double>() * y[k];
      }
      return e;
    };
    // Drawn: the sphere's disc differs from the picture without probes (over much of it: at a
    // single pixel its shading may happen to match what is behind it).
    const int cu = static_cast<int>(u), cv = static_cast<int>(v);
    int discPixels = 0, differing = 0;
    for (int py = static_cast<int>(v - r); py <= static_cast<int>(v + r); ++py)
      for (int px = static_cast<int>(u - r); px <= static_cast<int>(u + r); ++px) {
        if (std::hypot(px + 0.5 - u, py + 0.5 - v) > 0.8 * r) continue;
        ++discPixels;
        differing += std::abs(grey(a, px, py) - grey(b, px, py)) > 6;
      }
    EXPECT_GT(differing, discPixels / 4) << "no probe drawn at " << u << ", " << v;
    ++checked;
    // Above against below, left against right of the centre: where the SH says one side gets
    // 1.5 × the other's light, the picture is brighter there.
    const int o = static_cast<int>(0.6 * r);
    for (const auto& [du, dv] : {std::pair{0, o}, std::pair{o, 0}}) {
      const double e1 = expected(cu - du, cv - dv), e2 = expected(cu + du, cv + dv);
      ASSERT_GT(std::min(e1, e2), -1.0) << "the ray misses the sphere";
      if (!(e1 > 1.5 * e2 || e2 > 1.5 * e1) || std::min(e1, e2) <= 0) continue;
      ++decisive;
      const int g1 = grey(a, cu - du, cv - dv), g2 = grey(a, cu + du, cv + dv);
      agree += e1 > e2 ? g1 > g2 : g2 > g1;
      EXPECT_EQ(e1 > e2, g1 > g2) << "probe at " << centre.transpose() << ", offset " << du << ", "
                                  << dv << ": SH " << e1 << " vs " << e2 << ", picture " << g1
                                  << " vs " << g2;
    }
  }
  EXPECT_EQ(checked, 9);
  EXPECT_GE(decisive, 6);
  EXPECT_EQ(agree, decisive);

  // A truncated probes.bin: exit 1 naming it, no PNG; --no-probes leaves it unread.
  fs::resize_file(out / "probes.bin", 100);
  const fs::path never = dir / "never.png";
  EXPECT_EQ(runView(common + " --screenshot " + never.string(), errors), 1);
  EXPECT_NE(errors.find((out / "probes.bin").string() + ": cut short"), std::string::npos)
      << errors;
  EXPECT_FALSE(fs::exists(never));
  EXPECT_EQ(runView(common + " --no-probes --screenshot " + never.string(), errors), 0) << errors;
  EXPECT_EQ(runView(common + " --no-probes --probes " + (out / "probes.bin").string(), errors), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
