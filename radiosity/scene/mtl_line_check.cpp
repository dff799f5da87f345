#include "radiosity/scene/mtl_line_check.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_tokens.h"

namespace rad {
namespace {

std::string channels(const std::vector<double>& values) {
  std::ostringstream out;
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << values[i];
  return out.str();
}

}  // namespace

MtlLineCheck checkMtlText(const std::string& text, const std::string& file) {
  // Only the statements the solver uses are checked; Ka, d and the like are passed on untouched.
  static const std::set<std::string> kColours = {"Kd", "Ks", "Ke", "Tf", "Kt"};
  static const std::set<std::string> kScalars = {"Ni", "Ns"};

  MtlLineCheck result;
  // The Kd-1 warning of the current material, said when the material ends without a map_Kd
  // (with one, Kd 1 only lets the texture through as it is, which is what exporters mean).
  std::string kdOneWarning;
  auto endMaterial = [&] {
    if (!kdOneWarning.empty() && !result.materials.back().diffuseMap.present())
      logWarning(kdOneWarning);
    kdOneWarning.clear();
  };
  forEachLine(text, [&](int line, const std::vector<std::string>& tokens) {
    if (!tokens.empty()) {
      const std::string& keyword = tokens.front();
      if (keyword == "newmtl") {
        if (!result.materials.empty()) endMaterial();
        if (tokens.size() < 2) throw InputError(file, line, "'newmtl' needs a material name");
        // tinyobjloader keeps the rest of the line as the name but `usemtl` reads one word.
        if (tokens.size() > 2) {
          throw InputError(file, line,
                           "material name '" + tokens[1] + " " + tokens[2] +
                               "...' contains spaces, which are not supported");
        }
        // tinyobjloader ends a name at a NUL byte; control characters are never a real name.
        for (unsigned char ch : tokens[1])
          if (ch < 0x20 || ch == 0x7f)
            throw InputError(
                file, line,
                "material name contains a control character (byte " + std::to_string(ch) + ")");
        MaterialSource material;
        material.name = tokens[1];
        material.file = file;
        material.line = line;
        result.materials.push_back(std::move(material));
      } else if (result.materials.empty()) {
        // tinyobjloader would silently give these values to an unnamed material.
        throw InputError(file, line, "'" + keyword + "' before any 'newmtl'");
      } else if (kColours.count(keyword)) {
        const std::vector<double> rgb = parseNumbers(tokens, 3, 3, file, line);
        if (keyword == "Kd") {
          for (double c : rgb) {
            if (c < 0 || c > 1) {
              throw InputError(
                  file, line,
                  "Kd " + channels(rgb) + ": reflectance must be in [0, 1] in every channel");
            }
          }
          // Exporters write Kd 1 for white (often times a texture): accepted, but such a surface
          // keeps every bit of light it receives, so say so once, at its line.
          if (*std::max_element(rgb.begin(), rgb.end()) == 1)
            kdOneWarning = file + ":" + std::to_string(line) + ": Kd " + channels(rgb) +
                           ": reflectance 1 keeps all the light a surface receives; a closed "
                           "scene of such surfaces cannot converge (it stops at the iteration "
                           "budget)";
        } else if (keyword == "Ke") {
          for (double c : rgb) {
            if (c < 0) {
              throw InputError(file, line,
                               "Ke " + channels(rgb) + ": emission must be non-negative");
            }
          }
        }
      } else if (keyword == "map_Kd") {
        result.materials.back().diffuseMap = parseTextureMap(tokens, file, line);
      } else if (keyword == "map_Ke") {
        result.materials.back().emissionMap = parseTextureMap(tokens, file, line);
      } else if (keyword == "map_d") {
        result.materials.back().coverageMap = parseTextureMap(tokens, file, line);
      } else if (kScalars.count(keyword)) {
        parseNumbers(tokens, 1, 1, file, line);
      } else if (keyword == "illum") {
        long illum = 0;
        if (tokens.size() != 2 || !parseIntegerToken(tokens[1], &illum) || illum < 0) {
          throw InputError(file, line,
                           "'illum' needs one non-negative integer, found '" +
                               joinTokens({tokens.begin() + 1, tokens.end()}) + "'");
        }
      }
    }
    result.text += joinTokens(tokens);
    result.text += '\n';
  });
  if (!result.materials.empty()) endMaterial();
  return result;
}

}  // namespace rad
