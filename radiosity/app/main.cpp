// The `radiosity` command line. The only place that catches exceptions and chooses exit codes
// (here and in runCommand, exit_codes.h): 0 success, 1 bad input or a failed run, 2 bad usage
// (unknown option, missing argument), 3 a failed internal check (a bug in radiosity),
// 130 / 143 interrupted by SIGINT / SIGTERM.
#include <cstdio>
#include <exception>

#include "radiosity/app/commands.h"
#include "radiosity/app/exit_codes.h"
#include "radiosity/core/interrupt.h"

int main(int argc, char** argv) {
  CLI::App app{"radiosity: a global-illumination solver and lightmap baker"};
  app.require_subcommand(1);
  rad::CommandAction run;
  rad::registerSolveCommand(app, run);
  rad::registerBakeCommand(app, run);
  rad::registerRenderCommand(app, run);
  rad::registerCompareCommand(app, run);
  rad::registerRelightCommand(app, run);
  rad::registerUpdateCommand(app, run);
#ifdef RADIOSITY_HAS_VIEWER
  rad::registerViewCommand(app, run);
#endif

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "error: %s\nRun with --help for the options.\n", e.what());
    return rad::kExitUsage;
  } catch (const std::exception& e) {
    // An option's own callback refused its value (--sky, --sun: an InputError naming the
    // option): bad input, as when the command checks it later.
    std::fprintf(stderr, "error: %s\n", e.what());
    return rad::kExitError;
  }

  // Ctrl-C / SIGTERM: stop within a second, leave no partial output, exit 128 + signal.
  rad::installInterruptHandlers();
  return rad::runCommand(run);
}
