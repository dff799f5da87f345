#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace rad::testing {

// A radiosity process started in the background, for tests that signal it mid-run.
class ChildProcess {
 public:
  // argv[0] is the binary; stderr goes to stderrPath, stdout to /dev/null.
  ChildProcess(const std::vector<std::string>& argv, const std::string& stderrPath) {
    pid_ = ::fork();
    if (pid_ == 0) {
      const int err = ::open(stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int null = ::open("/dev/null", O_RDWR);
      ::dup2(null, 0);
      ::dup2(null, 1);
      ::dup2(err, 2);
      std::vector<char*> args;
      for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      ::execv(args[0], args.data());
      ::_exit(127);
    }
  }
  ~ChildProcess() {
    if (pid_ > 0 && !waited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  bool started() const { return pid_ > 0; }
  void signal(int sig) { ::kill(pid_, sig); }

  // Waits up to `seconds`; returns whether it ended. status() then holds the wait status.
  bool waitFor(double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (::waitpid(pid_, &status_, WNOHANG) == pid_) {
        waited_ = true;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return false;
  }
  // Whether the process is still running (it has not exited yet).
  bool running() {
    if (waited_) return false;
    if (::waitpid(pid_, &status_, WNOHANG) == pid_) waited_ = true;
    return !waited_;
  }
  int status() const { return status_; }
  // Whether the process has installed a handler for `sig` yet (Linux: the SigCgt mask of
  // /proc/<pid>/status). On a loaded machine start-up alone can take longer than a test's delay.
  bool catches(int sig) const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("SigCgt:", 0) == 0)
        return (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1)) & 1u;
    return false;
  }

  // Waits up to `seconds` until the process catches `sig` (its handler is installed: SigCgt in
  // /proc/<pid>/status), so a test does not signal it while it is still starting up; returns
  // whether it does.
  bool waitForHandler(int sig, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end && running()) {
      std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
      std::string line;
      while (std::getline(in, line))
        if (line.rfind("SigCgt:", 0) == 0 &&
            (std::stoull(line.substr(7), nullptr, 16) >> (sig - 1) & 1))
          return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  bool waited_ = false;
};

}  // namespace rad::testing
