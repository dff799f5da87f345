#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "radiosity/app/solve_job.h"

namespace rad {

// Each subcommand registers its options on the CLI11 app and sets `run` to its action when the
// user picks it. main() parses, then calls the action; the action throws on failure (InputError
// for bad input), and main() turns exceptions into messages and exit codes.
using CommandAction = std::function<void()>;

void registerSolveCommand(CLI::App& app, CommandAction& run);
void registerBakeCommand(CLI::App& app, CommandAction& run);
void registerRenderCommand(CLI::App& app, CommandAction& run);
void registerCompareCommand(CLI::App& app, CommandAction& run);
#ifdef RADIOSITY_HAS_VIEWER
void registerViewCommand(CLI::App& app, CommandAction& run);  // built with the VTK viewer only
#endif

// Common flags every command takes (--quiet).
void addCommonFlags(CLI::App& command);
// The --solver ... --bounces options, for every command that solves before its own work;
// `solverName` is parsed with parseSolverKind() when the command runs.
void addSolveOptions(CLI::App& command, SolveOptions& options, std::string& solverName);

}  // namespace rad
