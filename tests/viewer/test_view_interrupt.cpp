// `radiosity view --screenshot` interrupted, as solve/render/bake: a pending interrupt writes no
// PNG, and Ctrl-C during the run ends it with 130, "interrupted" and nothing left behind (how
// soon is bench/interrupt_latency.py's to measure; the 30 s below only guards against a hang).
// Needs an X display (Debian's VTK renders off-screen through X): run under xvfb-run -a.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "radiosity/core/interrupt.h"
#include "tests/robustness/child_process.h"
#include "tests/support/closed_cube.h"
#include "tests/support/run_command.h"
#include "viewer/solution_polydata.h"
#include "viewer/solution_viewer.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

class ViewInterrupt : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) GTEST_SKIP() << "no X display: run this test under xvfb-run -a";
  }
};

// Files in `dir` whose name starts with `stem` (the output and any temporary name next to it).
int filesStartingWith(const fs::path& dir, const std::string& stem) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    n += entry.path().filename().string().rfind(stem, 0) == 0;
  return n;
}

TEST_F(ViewInterrupt, APendingInterruptWritesNoScreenshot) {
  const PatchMesh mesh = testing::closedCube(0.1);
  const std::vector<Rgb> b(mesh.elementCount(), Rgb::all(1.0));
  ViewerOptions options;
  options.width = options.height = 96;
  SolutionViewer viewer(makeSolutionPolyData(mesh, b, {}, ToneMap{0.5}), ToneMap{0.5}, nullptr,
                        options);
  const fs::path dir = testing::scratchPath("view_pending_interrupt");
  fs::create_directories(dir);
  requestInterrupt(SIGINT);
  EXPECT_THROW(viewer.screenshot((dir / "shot.png").string()), Interrupted);
  clearInterrupt();
  EXPECT_EQ(filesStartingWith(dir, "shot"), 0) << "an interrupted screenshot left a file";
  // The same viewer, not interrupted, writes it: the refusal above was the interrupt's doing.
  viewer.screenshot((dir / "shot.png").string());
  EXPECT_TRUE(fs::is_regular_file(dir / "shot.png"));
  EXPECT_EQ(filesStartingWith(dir, "shot"), 1);
  fs::remove_all(dir);
}

TEST_F(ViewInterrupt, CtrlCDuringTheRunLeavesNoScreenshot) {
  const fs::path dir = testing::scratchPath("view_interrupt");
  fs::create_directories(dir);
  const fs::path err = dir / "stderr.txt";
  const std::string cornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";
  testing::ChildProcess child(
      {RADIOSITY_BINARY, "view", cornell, "--elements", "20000", "--solver", "gauss-seidel",
       "--screenshot", (dir / "shot.png").string(), "--size", "256x256", "--no-chart", "--quiet"},
      err.string());
  ASSERT_TRUE(child.started());
  // Past start-up (before the handlers are installed Ctrl-C simply kills the process; loading
  // VTK takes a while on a busy machine), into the form-factor pass.
  ASSERT_TRUE(child.waitForHandler(SIGINT, 30.0)) << "no SIGINT handler installed";
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_TRUE(child.running()) << "the run ended before the signal; make it longer";
  child.signal(SIGINT);
  ASSERT_TRUE(child.waitFor(30.0)) << "still running 30 s after Ctrl-C: it hangs";
  ASSERT_TRUE(WIFEXITED(child.status())) << "killed by signal " << WTERMSIG(child.status());
  EXPECT_EQ(WEXITSTATUS(child.status()), 130);
  std::ifstream in(err);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("interrupted"), std::string::npos) << text.str();
  EXPECT_EQ(filesStartingWith(dir, "shot"), 0) << "an interrupted view left a file";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rad
