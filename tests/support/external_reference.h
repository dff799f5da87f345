#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace rad::testing {

// Whether the tests run in CI (.ci/run: CI=true), where every external reference must run.
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string(ci) == "true";
}

}  // namespace rad::testing

// An independent reference the project did not write (the Khronos glTF validator, Blender) is
// missing: a skip on a developer's machine, a failure under CI=true, where
// `scripts/setup.sh --references` (called by scripts/test.sh) installs it. Returns from the
// calling function, like GTEST_SKIP.
#define RAD_MISSING_EXTERNAL_REFERENCE(what)                                          \
  do {                                                                                \
    if (::rad::testing::runningInCi())                                                \
      GTEST_FAIL() << what << " (CI=true: an external reference may not be skipped; " \
                   << "scripts/setup.sh --references installs it)";                   \
    else                                                                              \
      GTEST_SKIP() << what;                                                           \
  } while (0)
