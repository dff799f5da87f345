#include "radiosity/scene/mtl_texture_map.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_tokens.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

struct OptionRule {
  std::size_t minArgs, maxArgs;
  bool numeric;
  double identity;  // the value that leaves the mapping unchanged (numeric options); NaN: none
};

// The MTL specification's texture options and how many arguments each takes.
const std::map<std::string, OptionRule>& optionRules() {
  static const std::map<std::string, OptionRule> rules = {
      {"-blendu", {1, 1, false, 0}}, {"-blendv", {1, 1, false, 0}},  {"-cc", {1, 1, false, 0}},
      {"-clamp", {1, 1, false, 0}},  {"-imfchan", {1, 1, false, 0}}, {"-type", {1, 1, false, 0}},
      {"-bm", {1, 1, true, 1}},      {"-boost", {1, 1, true, 0}},    {"-texres", {1, 1, true, 0}},
      {"-mm", {2, 2, true, 0}},      {"-o", {1, 3, true, 0}},        {"-s", {1, 3, true, 1}},
      {"-t", {1, 3, true, 0}},
  };
  return rules;
}

bool isNumber(const std::string& token) {
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == '\0';
}

}  // namespace

TextureMapStatement parseTextureMap(const std::vector<std::string>& tokens,
                                    const std::string& mtlFile, int line) {
  const std::string& keyword = tokens.front();
  std::size_t k = 1;
  while (k < tokens.size() && tokens[k].size() > 1 && tokens[k][0] == '-') {
    const std::string option = tokens[k];
    const auto rule = optionRules().find(option);
    if (rule == optionRules().end())
      throw InputError(mtlFile, line, "'" + keyword + "': unknown texture option '" + option + "'");
    std::vector<std::string> args;
    ++k;
    while (k < tokens.size() && args.size() < rule->second.maxArgs &&
           (!rule->second.numeric || isNumber(tokens[k])))
      args.push_back(tokens[k++]);
    if (args.size() < rule->second.minArgs || k >= tokens.size())
      throw InputError(mtlFile, line,
                       "'" + keyword + "': option '" + option + "' needs " +
                           std::to_string(rule->second.minArgs) +
                           " value(s) and a file name after it");
    // Only what changes where a texel lands (scale, offset, turbulence, clamping) or which
    // channel is read matters for a colour or coverage map; the rest concerns bump and
    // reflection maps.
    bool changesMapping = option == "-imfchan" || (option == "-clamp" && args[0] == "on");
    if (option == "-s" || option == "-o" || option == "-t")
      for (const std::string& a : args)
        changesMapping |= std::strtod(a.c_str(), nullptr) != rule->second.identity;
    if (changesMapping)
      logWarning(mtlFile + ":" + std::to_string(line) + ": '" + keyword + "' option '" + option +
                 " " + joinTokens(args) +
                 "' is not supported and is ignored: the texture repeats unscaled over the "
                 "face's texture coordinates");
  }
  if (k >= tokens.size()) throw InputError(mtlFile, line, "'" + keyword + "' needs a file name");

  std::string name = joinTokens({tokens.begin() + static_cast<long>(k), tokens.end()});
  std::replace(name.begin(), name.end(), '\\', '/');  // as Windows exporters write folders
  const fs::path named(name);
  TextureMapStatement statement;
  statement.path = named.is_absolute()
                       ? named.string()
                       : (fs::path(mtlFile).parent_path() / named).lexically_normal().string();
  statement.file = mtlFile;
  statement.line = line;
  return statement;
}

}  // namespace rad
