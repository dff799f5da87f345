// The `radiosity` command line. The only place that catches exceptions and chooses exit codes:
// 0 success, 1 bad input or a failed run, 2 bad usage (unknown option, missing argument).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "radiosity/app/solve_job.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"

namespace {

void addSolveCommand(CLI::App& app, rad::SolveOptions& options, std::string& solverName, bool& quiet) {
  CLI::App* solve = app.add_subcommand("solve", "Solve the diffuse radiosity of a scene");
  solve->add_option("scene", options.scenePath, "OBJ scene file (materials from its MTL)")
      ->required();
  solve->add_option("--out", options.outputDir, "Output directory (created if missing)")->required();
  solve->add_option("--solver", solverName, "progressive (lazy rows) | southwell (progressive on all rows) | gauss-seidel | jacobi")
      ->default_val("progressive");
  solve->add_option("--rays", options.raysPerElement, "Hemisphere rays per element")
      ->default_val(options.raysPerElement);
  solve->add_option("--max-area", options.maxArea,
                    "Largest element area in scene units² (default: total area / --elements)");
  solve->add_option("--elements", options.targetElements,
                    "Approximate element count when --max-area is not given")
      ->default_val(options.targetElements)
      ->check(CLI::PositiveNumber);
  solve->add_option("--seed", options.seed, "Random seed")->default_val(options.seed);
  solve->add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->default_val(options.threads);
  solve->add_option("--tolerance", options.tolerance,
                    "Stop at this relative residual (gauss-seidel, jacobi) or unshot fraction "
                    "(progressive)")
      ->default_val(options.tolerance);
  solve->add_option("--max-iterations", options.maxIterations,
                    "Iteration budget: sweeps, bounces or shots (0: solver default)");
  solve->add_option("--bounces", options.bounces, "Jacobi only: exactly N bounces of light");
  solve->add_flag("--quiet,-q", quiet, "Only warnings and errors on stderr");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"radiosity: a global-illumination solver and lightmap baker"};
  app.require_subcommand(1);
  rad::SolveOptions options;
  std::string solverName = "progressive";
  bool quiet = false;
  addSolveCommand(app, options, solverName, quiet);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "error: %s\nRun with --help for the options.\n", e.what());
    return 2;
  }

  try {
    if (quiet) rad::setLogLevel(rad::LogLevel::Quiet);
    options.solver = rad::parseSolverKind(solverName);
    rad::SolveResult result = rad::runSolve(options);
    rad::writeSolveOutputs(options, result);
    return 0;
  } catch (const rad::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
