// Ctrl-C / SIGTERM during a long solve: the process reports the interrupt, exits with 128 +
// signal, and leaves no output directory or file behind. How soon it stops is a benchmark
// (bench/interrupt_latency.py), not an assertion: the 30 s below only guards against a hang.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "tests/robustness/child_process.h"
#include "tests/support/run_command.h"

namespace rad {
namespace {

const std::string kCornell = std::string(RADIOSITY_DATA_DIR) + "/cornell_box/cornell_box.obj";

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

struct InterruptCase {
  const char* name;
  int signal;
  double after;                   // seconds between the handlers' installation and the signal
  std::vector<std::string> args;  // solve options making the run last several seconds
};

void PrintTo(const InterruptCase& c, std::ostream* os) { *os << c.name; }

class Interrupt : public ::testing::TestWithParam<InterruptCase> {};

TEST_P(Interrupt, StopsWithItsSignalsExitCodeAndLeavesNothing) {
  const InterruptCase& c = GetParam();
  const auto out = testing::scratchPath(std::string("interrupt_") + c.name);
  const auto err = testing::scratchPath(std::string("stderr_of_interrupt_") + c.name);
  std::vector<std::string> argv{RADIOSITY_BINARY, "solve", kCornell, "--out", out.string()};
  argv.insert(argv.end(), c.args.begin(), c.args.end());
  testing::ChildProcess child(argv, err.string());
  ASSERT_TRUE(child.started());
  // On a busy machine start-up alone can take longer than `after`: count from the handlers.
  ASSERT_TRUE(child.waitForHandler(c.signal, 30.0)) << "no signal handler installed\n"
                                                    << readText(err);
  std::this_thread::sleep_for(std::chrono::duration<double>(c.after));
  // The delay is meant to land mid-run; on a loaded machine the process may not even have
  // installed its handlers yet, so wait (up to 10 s) until it has.
  for (int i = 0; i < 1000 && child.running() && !child.catches(c.signal); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(child.running()) << "the run ended before the signal; make it longer\n"
                               << readText(err);

  child.signal(c.signal);
  ASSERT_TRUE(child.waitFor(30.0)) << "still running 30 s after the signal: it hangs";
  ASSERT_TRUE(WIFEXITED(child.status())) << "killed by signal " << WTERMSIG(child.status());
  EXPECT_EQ(WEXITSTATUS(child.status()), 128 + c.signal);
  const std::string text = readText(err);
  EXPECT_NE(text.find(c.signal == SIGINT ? "interrupted" : "terminated"), std::string::npos)
      << text;
  EXPECT_FALSE(std::filesystem::exists(out)) << "an interrupted run left " << out;
  // Nothing next to it either (temporary files are written inside the output directory).
  for (const auto& entry : std::filesystem::directory_iterator(out.parent_path()))
    EXPECT_EQ(entry.path().filename().string().rfind(out.filename().string() + ".", 0),
              std::string::npos)
        << entry.path();
  std::filesystem::remove(err);
}

// During the form-factor pass (gathering solver, all rows up front: the watchdog ends it) and
// during progressive shooting (the solve loop notices the flag and unwinds).
INSTANTIATE_TEST_SUITE_P(
    Runs, Interrupt,
    ::testing::Values(InterruptCase{"sigint_form_factors",
                                    SIGINT,
                                    0.5,
                                    {"--elements", "20000", "--solver", "gauss-seidel", "--quiet"}},
                      InterruptCase{"sigterm_form_factors",
                                    SIGTERM,
                                    0.5,
                                    {"--elements", "20000", "--solver", "gauss-seidel", "--quiet"}},
                      InterruptCase{"sigint_shooting",
                                    SIGINT,
                                    1.0,
                                    {"--elements", "20000", "--tolerance", "0", "--max-iterations",
                                     "2000000000", "--quiet"}}),
    [](const ::testing::TestParamInfo<InterruptCase>& info) {
      return std::string(info.param.name);
    });

}  // namespace
}  // namespace rad
