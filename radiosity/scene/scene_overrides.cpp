#include "radiosity/scene/scene_overrides.h"

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>

#include "radiosity/core/errors.h"
#include "radiosity/scene/json_file.h"

namespace rad {
namespace {

using nlohmann::json;

// Names listed in an error, enough to spot a typo without flooding the terminal.
constexpr size_t kListedNames = 20;

// A key as a JSON pointer token (RFC 6901): "~" → "~0", "/" → "~1".
std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

// The distinct non-empty names, in order of first appearance, at most kListedNames then "…".
std::string nameList(const std::vector<std::string>& names) {
  std::set<std::string> seen;
  std::string out;
  for (const std::string& name : names) {
    if (name.empty() || !seen.insert(name).second) continue;
    if (seen.size() > kListedNames) return out + ", …";
    out += (out.empty() ? "" : ", ") + name;
  }
  return out.empty() ? "none" : out;
}

bool allDigits(const std::string& key) {
  return !key.empty() && key.find_first_not_of("0123456789") == std::string::npos;
}

// The light a key names by index: decimal digits, no leading zero, below `count`.
std::optional<size_t> lightIndex(const std::string& key, size_t count) {
  if (!allDigits(key) || (key.size() > 1 && key[0] == '0')) return std::nullopt;
  if (key.size() > 18) return std::nullopt;  // beyond any scene, and beyond what stoull reads
  const size_t index = std::stoull(key);
  if (index >= count) return std::nullopt;
  return index;
}

// Reads the file's values, each error naming the file, the line and the JSON pointer.
class OverrideReader {
 public:
  OverrideReader(const std::string& path, const std::string& text) : path_(path), text_(text) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw InputError(path_, lineOfPointer(text_, pointer),
                     pointer.empty() ? what : pointer + ": " + what);
  }

  void allowOnly(const json& j, const std::string& pointer,
                 std::initializer_list<const char*> known) const {
    for (const auto& item : j.items()) {
      bool ok = false;
      for (const char* k : known) ok = ok || item.key() == k;
      if (ok) continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(pointer + "/" + pointerToken(item.key()),
           "unknown key \"" + item.key() + "\" (known: " + list + ")");
    }
  }

  void requireObject(const json& j, const std::string& pointer, const std::string& what) const {
    if (!j.is_object()) fail(pointer, "must be a JSON object (" + what + ")");
  }

  // An array of 3 finite numbers.
  Rgb colour(const json& v, const std::string& pointer) const {
    if (!v.is_array() || v.size() != 3) fail(pointer, "must be an array of 3 numbers [r, g, b]");
    Rgb out;
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number()) fail(pointer, "must be an array of 3 numbers [r, g, b]");
      out[k] = v[k].get<double>();
    }
    if (!out.isFinite()) fail(pointer, "must be finite");
    return out;
  }

  // One number for every channel, or an RGB triple; finite and not negative.
  Rgb scale(const json& v, const std::string& pointer) const {
    Rgb out;
    if (v.is_number()) {
      out = Rgb::all(v.get<double>());
      if (!out.isFinite()) fail(pointer, "must be finite");
    } else if (v.is_array()) {
      out = colour(v, pointer);
    } else {
      fail(pointer, "must be a number or an array of 3 numbers [r, g, b]");
    }
    if (out.minComponent() < 0) fail(pointer, "must not be negative");
    return out;
  }

 private:
  const std::string& path_;
  const std::string& text_;
};

MaterialOverride readMaterial(const OverrideReader& r, const json& j, const std::string& pointer) {
  r.requireObject(j, pointer, "with \"diffuse\" and/or \"emission\"");
  r.allowOnly(j, pointer, {"diffuse", "emission", "comment"});
  MaterialOverride out;
  if (j.contains("diffuse")) {
    out.diffuse = r.colour(j.at("diffuse"), pointer + "/diffuse");
    // A reflectance above 1 would make light from nothing, and the solve would not converge.
    if (out.diffuse->minComponent() < 0 || out.diffuse->maxComponent() > 1)
      r.fail(pointer + "/diffuse", "each channel must be in [0, 1]");
  }
  if (j.contains("emission")) {
    out.emission = r.colour(j.at("emission"), pointer + "/emission");
    if (out.emission->minComponent() < 0) r.fail(pointer + "/emission", "must not be negative");
  }
  // An entry that changes nothing is most likely a misspelt or misplaced one.
  if (!out.diffuse && !out.emission) r.fail(pointer, "sets neither \"diffuse\" nor \"emission\"");
  return out;
}

void readMaterials(const OverrideReader& r, const json& j,
                   const std::vector<std::string>& materialNames, SceneOverrides& out) {
  r.requireObject(j, "/materials", "material names to their overrides");
  for (const auto& item : j.items()) {
    const std::string pointer = "/materials/" + pointerToken(item.key());
    std::vector<int> indices;
    for (size_t i = 0; i < materialNames.size(); ++i)
      if (materialNames[i] == item.key()) indices.push_back(static_cast<int>(i));
    if (indices.empty())
      r.fail(pointer,
             "no material named '" + item.key() + "' (materials: " + nameList(materialNames) + ")");
    const MaterialOverride m = readMaterial(r, item.value(), pointer);
    for (int i : indices) out.materials[i] = m;
  }
}

void readLights(const OverrideReader& r, const json& j, const std::vector<std::string>& lightGroups,
                SceneOverrides& out) {
  r.requireObject(j, "/lights", "light indices or group names to their scale");
  const size_t count = lightGroups.size();
  // Kept apart so that an index's scale wins over its group's whatever the keys' order.
  std::vector<std::optional<Rgb>> byIndex(count), byGroup(count);
  for (const auto& item : j.items()) {
    const std::string& key = item.key();
    const std::string pointer = "/lights/" + pointerToken(key);
    const std::optional<size_t> index = lightIndex(key, count);
    std::vector<size_t> members;
    if (!index)
      for (size_t i = 0; i < count; ++i)
        if (!key.empty() && lightGroups[i] == key) members.push_back(i);
    if (!index && members.empty()) {
      if (allDigits(key) && key[0] == '0' && key.size() > 1)
        r.fail(pointer, "no light or light group named '" + key +
                            "' (a light's index is written without leading zeros)");
      if (allDigits(key))
        r.fail(pointer, "no light with index " + key + " (the scene has " + std::to_string(count) +
                            " lights)");
      r.fail(pointer,
             "no light or light group named '" + key + "' (groups: " + nameList(lightGroups) + ")");
    }
    const json& entry = item.value();
    r.requireObject(entry, pointer, "with \"scale\"");
    r.allowOnly(entry, pointer, {"scale", "comment"});
    if (!entry.contains("scale")) r.fail(pointer, "missing key \"scale\"");
    const Rgb scale = r.scale(entry.at("scale"), pointer + "/scale");
    if (index) byIndex[*index] = scale;
    for (size_t i : members) byGroup[i] = scale;
  }
  for (size_t i = 0; i < count; ++i)
    if (byIndex[i] || byGroup[i]) out.lightScale[i] = byIndex[i] ? *byIndex[i] : *byGroup[i];
}

}  // namespace

SceneOverrides loadSceneOverrides(const std::string& path,
                                  const std::vector<std::string>& materialNames,
                                  const std::vector<std::string>& lightGroups) {
  const JsonFile file = readJsonFile(path, "override");
  const OverrideReader reader(path, file.text);
  const json& j = file.value;
  if (!j.is_object())
    reader.fail("",
                "an override file holds one JSON object (with \"materials\" and/or \"lights\")");
  reader.allowOnly(j, "", {"materials", "lights", "comment"});
  SceneOverrides out;
  out.lightScale.assign(lightGroups.size(), Rgb::all(1));
  if (j.contains("materials")) readMaterials(reader, j.at("materials"), materialNames, out);
  if (j.contains("lights")) readLights(reader, j.at("lights"), lightGroups, out);
  return out;
}

void applyMaterialOverride(Material& material, const MaterialOverride& change) {
  if (change.diffuse) material.diffuse = *change.diffuse;
  if (change.emission) material.emission = *change.emission;
}

}  // namespace rad
