#pragma once

// What every command's options share: whether the user gave an option, the refusal of an option
// that the chosen method or mode does not use, and the options every command binds alike.
#include <CLI/CLI.hpp>
#include <set>
#include <string>

#include "radiosity/core/named_values.h"

namespace rad {

// The scene positional's help: both formats load (scene/scene_loader.h).
inline constexpr const char* kSceneFileHelp = "scene file (OBJ or glTF)";

// --quiet, -q: only warnings and errors on stderr. Every command takes it.
void addCommonFlags(CLI::App& command);

// --threads N (0: every core), checked here (non-negative); read through ThreadLimit
// (pipeline/thread_limit.h).
CLI::Option* addThreadsOption(CLI::App& command, int& threads);

// Checks of a number's sign, with a message a user reads ("must be > 0, not -2"); CLI11's own
// PositiveNumber and NonNegativeNumber print the range up to the largest double. A value they
// refuse is a usage error (exit 2), as every check on the command line is.
const CLI::Validator& positiveNumber();
const CLI::Validator& nonNegativeNumber();

// The long names ("--rays") of the options the user gave to `command`. Defaults are not given:
// an option counts only when it is on the command line.
std::set<std::string> givenOptions(const CLI::App& command);
bool wasGiven(const CLI::App& command, const std::string& name);  // false when not bound

// The one wording of an unused option: throws InputError "NAME is not used: WHY" when the user
// gave `name` to `command`. Defaults never count, so a method that ignores an option's default
// is not an error; the same option given explicitly is.
void refuseIfGiven(const CLI::App& command, const std::string& name, const std::string& why);

// An option whose value is one of an enum's names (its NameTable, the one list of them): the
// check CLI11 prints in --help lists them, and refuses any other (a usage error, exit 2); case
// is ignored.
template <class Enum>
CLI::Option* addChoiceOption(CLI::App& command, const std::string& name, Enum& value,
                             const NameTable<Enum>& table, const std::string& help) {
  return command
      .add_option_function<std::string>(
          name,
          [&value, &table, name](const std::string& text) { value = parseName(table, text, name); },
          help)
      ->check(CLI::IsMember(tableNames(table), CLI::ignore_case))
      ->default_str(nameOf(table, value));
}

}  // namespace rad
