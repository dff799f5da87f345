#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rad::testing {

struct CommandResult {
  // The exit status; a process killed by a signal (a crash) has 128 + the signal, which no
  // expected exit code equals (input errors 1, usage 2, internal errors 3): tests compare exit
  // codes exactly, so a crash never passes for a refusal.
  int exitCode = -1;
  int signal = 0;  // the signal that killed it, or 0
  std::string stderrText;
};

// Runs the radiosity binary with `arguments` (shell words), capturing its exit code and stderr.
// The shell execs the binary, so a signal that kills it reaches this process's status as such.
inline CommandResult runRadiosity(const std::string& arguments) {
  const auto errFile = std::filesystem::temp_directory_path() /
                       ("radiosity_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string command = "exec " + std::string(RADIOSITY_BINARY) + " " + arguments +
                              " >/dev/null 2>" + errFile.string() + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
    result.exitCode = 128 + result.signal;
  } else {
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::ifstream in(errFile);
  std::stringstream text;
  text << in.rdbuf();
  result.stderrText = text.str();
  if (result.signal != 0)
    result.stderrText += "\n[killed by signal " + std::to_string(result.signal) + "]";
  std::filesystem::remove(errFile);
  return result;
}

// A fresh, empty scratch directory path (not created).
inline std::filesystem::path scratchPath(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("radiosity_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(path);
  return path;
}

}  // namespace rad::testing
