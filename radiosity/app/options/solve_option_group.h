#pragma once

// The options of a solve (SolveOptions), bound alike by every command that solves (solve, render,
// compare, bake, view) so that they share solve's defaults and can reuse what solve wrote. Each
// option sits in one of three CLI11 groups (its --help heading), and the groups say which
// options a command that does not solve must refuse.
#include <CLI/CLI.hpp>
#include <string>

#include "radiosity/pipeline/solve_options.h"

namespace rad {

// Binds --lights ... --receiver-points to `options` (the command keeps both alive).
void addSolveOptions(CLI::App& command, SolveOptions& options);

// When the command runs: checks the values (validateSolveOptions) and that every solve option
// given applies to the chosen solver and form factors (checkOptionsApply); InputError otherwise.
void finishSolveOptions(const CLI::App& command, const SolveOptions& options);

// A command whose method does not solve: the values are checked as above, and every option that
// only the solve reads is an error "NAME is not used: WHY" (e.g. WHY = "--method path does not
// solve radiosity"). The scene input (--lights, --sky, ...), --seed and --threads remain.
void finishWithoutSolve(const CLI::App& command, const SolveOptions& options,
                        const std::string& whyNoSolve);

// A command that neither loads the scene nor solves (view DIR): every option of addSolveOptions
// given is an error.
void refuseAllSolveOptions(const CLI::App& command, const std::string& why);

}  // namespace rad
