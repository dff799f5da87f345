// The viewer's keys on a real window (run under xvfb-run): every listed key is handled, the
// colouring follows the scalar, and picking finds the element under the cursor.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "radiosity/core/errors.h"
#include "tests/support/closed_cube.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_viewer.h"

namespace rad {
namespace {

class ViewerKeys : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) GTEST_SKIP() << "no X display: run this test under xvfb-run -a";
  }
};

TEST_F(ViewerKeys, EveryHelpKeyIsHandledAndPickingFindsTheFacingWall) {
  const PatchMesh mesh = testing::closedCube(0.02);
  std::vector<Rgb> b(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) b[e] = Rgb::all(1.0 + mesh.patch(e));
  ViewerOptions options;
  options.width = options.height = 200;
  // Outside the cube at z = -2, looking +z: back faces are culled, so the wall seen is the far one
  // (z = 1), patch 1 of closedCube.
  options.camera = Camera{{0.5, 0.5, -2}, {0.5, 0.5, 0.5}, {0, 1, 0}, 30};
  SolutionViewer viewer(makeSolutionPolyData(mesh, b, {}, ToneMap{0.1}), ToneMap{0.1}, nullptr,
                        options);
  for (const char* key : {"1", "2", "3", "4", "5", "6",     "7", "8", "9", "v", "e", "o",
                          "u", "u", "h", "x", "r", "space", "g", "b", "a", "l", "i"})
    EXPECT_TRUE(viewer.handleKey(key, 100, 100)) << key;
  EXPECT_FALSE(viewer.handleKey("w", 100, 100));  // VTK's wireframe key is not ours
  // Each key starts a line of the on-screen help.
  const std::string help = "\n" + SolutionViewer::keyHelp();
  for (const char* key : {"h ", "1 ... 9 ", "v ", "e ", "o ", "u ", "p ", "l ", "x ", "i ",
                          "space ", "g ", "b ", "a ", "r ", "q "})
    EXPECT_NE(help.find(std::string("\n") + key), std::string::npos) << key;

  const auto png = std::filesystem::temp_directory_path() /
                   ("viewer_keys_" + std::to_string(::getpid()) + ".png");
  viewer.screenshot(png.string());  // renders, so the picker sees the scene
  ::testing::internal::CaptureStdout();
  viewer.pickAt(100, 100);
  const std::string printed = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(printed.find("patch 1,"), std::string::npos) << printed;
  EXPECT_THROW(viewer.showRows(mesh.elementCount()), InputError);
  std::filesystem::remove(png);
}

// The layout rule (no window needed): the panel shows from 640 px wide, the bar's strip is
// 110 px (a quarter of narrower windows) and never overlaps the scene or the panel.
TEST(ViewerLayout, PanelHidesInSmallWindowsAndTheBarHasItsOwnStrip) {
  const ViewerLayout large = SolutionViewer::layoutFor(1280, 720, true);
  EXPECT_TRUE(large.chart);
  EXPECT_NEAR(large.barRight, 0.64, 1e-12);
  EXPECT_NEAR((large.barRight - large.sceneRight) * 1280, 110, 1e-9);
  EXPECT_EQ(large.barFontSize, 12);
  EXPECT_FALSE(SolutionViewer::layoutFor(1280, 720, false).chart);
  EXPECT_FALSE(SolutionViewer::layoutFor(639, 720, true).chart);
  EXPECT_FALSE(SolutionViewer::layoutFor(1280, 239, true).chart);
  const ViewerLayout small = SolutionViewer::layoutFor(400, 400, true);
  EXPECT_FALSE(small.chart);
  EXPECT_EQ(small.barRight, 1.0);
  EXPECT_NEAR(small.sceneRight, 0.75, 1e-12);
  EXPECT_EQ(small.barFontSize, 10);
  const ViewerLayout tiny = SolutionViewer::layoutFor(200, 150, false);
  EXPECT_EQ(tiny.sceneRight, 1.0);  // no room for the bar
}

}  // namespace
}  // namespace rad
