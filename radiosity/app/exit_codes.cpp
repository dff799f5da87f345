#include "radiosity/app/exit_codes.h"

#include <cstdio>
#include <exception>

#include "radiosity/core/check.h"
#include "radiosity/core/interrupt.h"

namespace rad {

int runCommand(const std::function<void()>& command) {
  try {
    if (command) command();
    return kExitSuccess;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "radiosity: %s\n", e.what());
    return e.exitCode();
  } catch (const CheckFailure& e) {
    std::fprintf(stderr, "radiosity: internal error (a bug, please report it): %s\n", e.what());
    return kExitBug;
  } catch (const std::exception& e) {
    // InputError messages already read "file:line: what".
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitError;
  }
}

}  // namespace rad
