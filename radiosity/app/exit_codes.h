#pragma once

#include <functional>

namespace rad {

// The `radiosity` command's exit codes (main.cpp; 128 + signal when interrupted).
enum ExitCode : int {
  kExitSuccess = 0,
  kExitError = 1,  // bad input (InputError) or a failed run
  kExitUsage = 2,  // unknown option, missing argument
  kExitBug = 3,    // a failed internal check (CheckFailure): a bug in radiosity
};

// Runs a command and turns what it throws into an exit code, with its message on stderr:
// CheckFailure → kExitBug ("internal error"), Interrupted → 128 + signal, any other
// std::exception → kExitError ("error: ..."). Returns kExitSuccess when it throws nothing.
int runCommand(const std::function<void()>& command);

}  // namespace rad
