#include "radiosity/scene/obj_line_check.h"

#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/obj_tokens.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// Counts of what the OBJ has defined so far: indices refer to these (negative ones relatively).
struct DefinedCounts {
  long vertices = 0;
  long texcoords = 0;
  long normals = 0;
};

const char* statementName(const std::string& keyword) {
  if (keyword == "f") return "face";
  if (keyword == "l") return "line";
  return "point";
}

void checkIndex(const std::string& token, long defined, const char* kind,
                const std::string& keyword, const std::string& file, int line) {
  const std::string where = std::string(statementName(keyword)) + ": " + kind + " index ";
  long index = 0;
  if (!parseIntegerToken(token, &index)) {
    throw InputError(file, line, where + "'" + token + "' is not an integer");
  }
  if (index == 0) {
    throw InputError(file, line, where + "0 is invalid (OBJ indices start at 1)");
  }
  if (index > defined || -index > defined) {
    throw InputError(file, line,
                     where + std::to_string(index) + " is out of range (" +
                         std::to_string(defined) + " defined before this line)");
  }
}

// One vertex reference of an f/l/p statement: "v", "v/vt", "v//vn" or "v/vt/vn".
void checkVertexRef(const std::string& ref, const DefinedCounts& counts, const std::string& keyword,
                    const std::string& file, int line) {
  std::vector<std::string> parts(1);
  for (char c : ref) {
    if (c == '/') {
      parts.emplace_back();
    } else {
      parts.back() += c;
    }
  }
  // tinyobjloader accepts an empty texture index only in the "v//vn" form.
  const bool shapeOk = parts.size() <= 3 && !parts[0].empty() &&
                       (parts.size() < 2 || !parts[1].empty() || parts.size() == 3) &&
                       (parts.size() < 3 || !parts[2].empty());
  if (!shapeOk) {
    throw InputError(file, line,
                     std::string(statementName(keyword)) + ": malformed vertex reference '" + ref +
                         "' (expected v, v/vt, v//vn or v/vt/vn)");
  }
  checkIndex(parts[0], counts.vertices, "vertex", keyword, file, line);
  if (parts.size() >= 2 && !parts[1].empty()) {
    checkIndex(parts[1], counts.texcoords, "texture coordinate", keyword, file, line);
  }
  if (parts.size() == 3) checkIndex(parts[2], counts.normals, "normal", keyword, file, line);
}

std::string materialName(const std::vector<std::string>& tokens, const std::string& file,
                         int line) {
  if (tokens.size() < 2) throw InputError(file, line, "'usemtl' needs a material name");
  if (tokens.size() > 2) {
    throw InputError(file, line,
                     "material name '" + joinTokens({tokens.begin() + 1, tokens.end()}) +
                         "' contains spaces, which are not supported");
  }
  return tokens[1];
}

class ObjChecker {
 public:
  explicit ObjChecker(std::string objPath)
      : path_(std::move(objPath)), dir_(fs::path(path_).parent_path()) {}

  ObjLineCheck run() {
    std::string text;
    if (!readTextFile(path_, &text)) throw InputError(path_, 0, "cannot open OBJ file");
    result_.objText.reserve(text.size());
    forEachLine(text, [this](int line, const std::vector<std::string>& tokens) {
      if (statement(tokens, line)) result_.objText += joinTokens(tokens);
      result_.objText += '\n';
    });
    result_.vertexCount = counts_.vertices;
    result_.texcoordCount = counts_.texcoords;
    return std::move(result_);
  }

 private:
  // Checks one line; returns whether tinyobjloader should see it.
  bool statement(const std::vector<std::string>& tokens, int line) {
    if (tokens.empty()) return false;
    const std::string& keyword = tokens.front();
    if (keyword == "v") {
      parseNumbers(tokens, 3, std::numeric_limits<std::size_t>::max(), path_, line);
      ++counts_.vertices;
      result_.vertexLines.push_back(line);
    } else if (keyword == "vt") {
      parseNumbers(tokens, 1, 3, path_, line);  // u [v [w]], as the OBJ specification allows
      ++counts_.texcoords;
    } else if (keyword == "vn") {
      ++counts_.normals;
    } else if (keyword == "f" || keyword == "l" || keyword == "p") {
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        checkVertexRef(tokens[k], counts_, keyword, path_, line);
      }
      if (keyword == "f") face(tokens.size() - 1, line);
    } else if (keyword == "usemtl") {
      useMaterial(materialName(tokens, path_, line), line);
    } else if (keyword == "mtllib") {
      return materialLibraries(tokens, line);
    } else if (keyword != "g" && keyword != "o") {
      return false;  // smoothing groups, curves, tags...: nothing the solver reads
    }
    return true;
  }

  void face(std::size_t size, int line) {
    if (size < 3) {
      throw InputError(path_, line,
                       "face has " + std::to_string(size) + " vertices; a face needs at least 3");
    }
    if (size > 255) {  // tinyobjloader stores face sizes in an unsigned char
      throw InputError(path_, line,
                       "face has " + std::to_string(size) + " vertices; at most 255 are supported");
    }
    result_.faceLines.push_back(line);
    result_.faceSizes.push_back(static_cast<int>(size));
  }

  void useMaterial(const std::string& name, int line) {
    if (materialIndex_.count(name)) return;
    std::string loaded;
    for (const std::string& library : libraryNames_) {
      loaded += (loaded.empty() ? "" : ", ") + library;
    }
    throw InputError(path_, line,
                     "missing material '" + name + "' (" +
                         (loaded.empty() ? std::string("no mtllib before this line")
                                         : "not defined in " + loaded) +
                         ")");
  }

  bool materialLibraries(const std::vector<std::string>& tokens, int line) {
    if (tokens.size() < 2) throw InputError(path_, line, "'mtllib' needs a file name");
    for (std::size_t k = 1; k < tokens.size(); ++k) {
      const fs::path named(tokens[k]);
      const fs::path resolved = named.is_absolute() ? named : dir_ / named;
      std::error_code ec;
      fs::path key = fs::weakly_canonical(resolved, ec);
      if (ec) key = resolved.lexically_normal();
      if (!loadedLibraries_.insert(key.string()).second) continue;

      std::string text;
      if (!readTextFile(resolved.string(), &text)) {
        throw InputError(path_, line,
                         "cannot open material library '" + tokens[k] + "' (looked for " +
                             resolved.string() + ")");
      }
      MtlLineCheck library = checkMtlText(text, resolved.string());
      for (MaterialSource& material : library.materials) addMaterial(std::move(material));
      result_.mtlText += library.text;
      libraryNames_.push_back(tokens[k]);
    }
    // mtlText reaches tinyobjloader whole at the first `mtllib`; later ones would re-read nothing.
    const bool first = !mtllibSeen_;
    mtllibSeen_ = true;
    return first;
  }

  void addMaterial(MaterialSource material) {
    const auto found = materialIndex_.find(material.name);
    if (found != materialIndex_.end()) {
      // tinyobjloader resolves `usemtl` to the first definition; say so rather than guess.
      const MaterialSource& first = result_.materials[found->second];
      logWarning(material.file + ":" + std::to_string(material.line) + ": material '" +
                 material.name + "' is defined again; the first definition (" + first.file + ":" +
                 std::to_string(first.line) + ") is used");
    } else {
      materialIndex_.emplace(material.name, static_cast<int>(result_.materials.size()));
    }
    result_.materials.push_back(std::move(material));
  }

  std::string path_;
  fs::path dir_;
  ObjLineCheck result_;
  DefinedCounts counts_;
  std::map<std::string, int> materialIndex_;
  std::set<std::string> loadedLibraries_;
  std::vector<std::string> libraryNames_;
  bool mtllibSeen_ = false;
};

}  // namespace

ObjLineCheck checkObjFile(const std::string& objPath) { return ObjChecker(objPath).run(); }

}  // namespace rad
