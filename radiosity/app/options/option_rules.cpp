#include "radiosity/app/options/option_rules.h"

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"

namespace rad {

namespace {

// A number whose sign `accepts`; `rule` names it in --help and in the message.
CLI::Validator signCheck(const std::string& rule, bool (*accepts)(double)) {
  return CLI::Validator(
      [rule, accepts](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "must be a number, not " + text;
        if (!accepts(value)) return "must be " + rule + ", not " + text;
        return {};
      },
      "NUMBER " + rule);
}

}  // namespace

const CLI::Validator& positiveNumber() {
  static const CLI::Validator check = signCheck("> 0", [](double v) { return v > 0; });
  return check;
}

const CLI::Validator& nonNegativeNumber() {
  static const CLI::Validator check = signCheck(">= 0", [](double v) { return v >= 0; });
  return check;
}

void addCommonFlags(CLI::App& command) {
  command.add_flag_callback(
      "--quiet,-q", [] { setLogLevel(LogLevel::Quiet); }, "Only warnings and errors on stderr");
}

CLI::Option* addThreadsOption(CLI::App& command, int& threads) {
  return command.add_option("--threads", threads, "Worker threads (0: all cores)")
      ->default_val(threads)
      ->check(nonNegativeNumber());
}

std::set<std::string> givenOptions(const CLI::App& command) {
  std::set<std::string> given;
  for (const CLI::Option* option : command.get_options())
    if (option->count() > 0) given.insert(option->get_name());
  return given;
}

bool wasGiven(const CLI::App& command, const std::string& name) {
  // An option the command does not bind was not given to it (a group shared by commands that
  // bind only some of its options asks about all of them).
  const CLI::Option* option = command.get_option_no_throw(name);
  return option && option->count() > 0;
}

void refuseIfGiven(const CLI::App& command, const std::string& name, const std::string& why) {
  if (wasGiven(command, name)) throw InputError(name + " is not used: " + why);
}

}  // namespace rad
