#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace rad {

// Each subcommand registers its options on the CLI11 app and sets `run` to its action when the
// user picks it. main() parses, then calls the action; the action throws on failure (InputError
// for bad input), and main() turns exceptions into messages and exit codes. The options the
// commands share, and the rule that an option the chosen method does not use is an error, are
// in app/options/.
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

}  // namespace rad
