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
  int exitCode = -1;
  std::string stderrText;
};

// Runs the radiosity binary with `arguments` (shell words), capturing its exit code and stderr.
inline CommandResult runRadiosity(const std::string& arguments) {
  const auto errFile = std::filesystem::temp_directory_path() /
                       ("radiosity_stderr_" + std::to_string(::getpid()) + ".txt");
  const std::string command = std::string(RADIOSITY_BINARY) + " " + arguments + " >/dev/null 2>" +
                              errFile.string() + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(errFile);
  std::stringstream text;
  text << in.rdbuf();
  result.stderrText = text.str();
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
