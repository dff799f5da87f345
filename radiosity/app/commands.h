#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <set>
#include <string>

#include "radiosity/pipeline/solve_options.h"

namespace rad {

// Each subcommand registers its options on the CLI11 app and sets `run` to its action when the
// user picks it. main() parses, then calls the action; the action throws on failure (InputError
// for bad input), and main() turns exceptions into messages and exit codes.
using CommandAction = std::function<void()>;

void registerSolveCommand(CLI::App& app, CommandAction& run);
void registerBakeCommand(CLI::App& app, CommandAction& run);
void registerRenderCommand(CLI::App& app, CommandAction& run);
void registerCompareCommand(CLI::App& app, CommandAction& run);
void registerRelightCommand(CLI::App& app, CommandAction& run);
void registerUpdateCommand(CLI::App& app, CommandAction& run);
#ifdef RADIOSITY_HAS_VIEWER
void registerViewCommand(CLI::App& app, CommandAction& run);  // built with the VTK viewer only
#endif

// Common flags every command takes (--quiet).
void addCommonFlags(CLI::App& command);
// The --solver ... --bounces options, for every command that solves before its own work, with
// the same defaults everywhere; `solverName` is parsed with parseSolverKind() when the command
// runs.
void addSolveOptions(CLI::App& command, SolveOptions& options, std::string& solverName);
// The long names ("--rays") of the options the user gave to `command`.
std::set<std::string> givenOptions(const CLI::App& command);
// What a solving command does when it runs: parses the solver name, checks the options' values
// and that every solve option given applies to the chosen method (InputError otherwise). With
// `whyNoSolve` (e.g. "--method path does not solve radiosity"), the command will not solve at
// all, and every solve-only option given is an error saying so.
void finishSolveOptions(const CLI::App& command, SolveOptions& options,
                        const std::string& solverName, const std::string& whyNoSolve = "");

}  // namespace rad
