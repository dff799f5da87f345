#include "radiosity/scene/scene_loader.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/gltf_loader.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

// What the first bytes of a file say it is.
enum class Content { Text, BinaryGltf, Json, Ply };

// One format: how to recognise it and how to load it. A format radiosity recognises but does
// not read (PLY) has no loader.
struct SceneFormat {
  const char* name;       // for messages: "binary glTF"
  const char* extension;  // lower case, with the dot
  Content content;        // what its first bytes look like (Text: no magic; any text)
  Scene (*load)(const std::string& path, UnreadableTextures);  // nullptr: recognised, not read
};

const SceneFormat kFormats[] = {
    {"OBJ", ".obj", Content::Text, &loadObjScene},
    {"binary glTF", ".glb", Content::BinaryGltf, &loadGltfScene},
    {"glTF", ".gltf", Content::Json, &loadGltfScene},
    {"PLY", ".ply", Content::Ply, nullptr},
};

Content sniff(const std::string& head) {
  if (head.compare(0, 4, "glTF") == 0) return Content::BinaryGltf;
  if (head.compare(0, 3, "ply") == 0 &&
      (head.size() == 3 || std::isspace(static_cast<unsigned char>(head[3]))))
    return Content::Ply;
  // JSON: an object after optional white space (and a UTF-8 byte order mark).
  size_t i = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
  if (i < head.size() && head[i] == '{') return Content::Json;
  return Content::Text;
}

const char* describe(Content content) {
  switch (content) {
    case Content::BinaryGltf:
      return "binary glTF";
    case Content::Json:
      return "JSON";
    case Content::Ply:
      return "PLY";
    case Content::Text:
      break;
  }
  return "text";
}

// The extension of the file name (lower case, with the dot), or "" for none.
std::string extensionOf(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
      dot == (slash == std::string::npos ? 0 : slash + 1))
    return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

[[noreturn]] void unsupported(const std::string& path, const std::string& what) {
  throw InputError(
      path, 0,
      "unsupported scene format (" + what + "): radiosity reads " + readableSceneFormats());
}

}  // namespace

Scene loadScene(const std::string& path, const LightInput& lights, const TwoSidedInput& twoSided,
                UnreadableTextures unreadable) {
  Scene scene = loadScene(path, unreadable);
  // The scene's own lights (glTF's KHR_lights_punctual) come first, then the lights file's.
  for (Light& light : findSceneLights(path, lights)) scene.lights.push_back(std::move(light));
  applyTwoSidedInput(scene, twoSided);
  const int backSides = addBackSides(scene);
  if (backSides > 0)
    logInfo(std::to_string(backSides) + " two-sided polygons: each side gets its own radiosity");
  return scene;
}

bool sceneHasOwnLights(const std::string& path) {
  const std::string ext = extensionOf(path);
  return (ext == ".gltf" || ext == ".glb") && gltfSceneHasLights(path);
}

std::string readableSceneFormats() {
  std::string list;
  for (const SceneFormat& f : kFormats)
    if (f.load) list += (list.empty() ? "" : ", ") + std::string(f.name) + " (" + f.extension + ")";
  return list;
}

Scene loadScene(const std::string& path, UnreadableTextures unreadable) {
  std::string head;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot open scene file");
    char buffer[64];
    in.read(buffer, sizeof buffer);
    if (in.bad()) throw InputError(path, 0, "cannot read scene file");
    head.assign(buffer, static_cast<size_t>(in.gcount()));
  }
  const Content content = sniff(head);
  const std::string ext = extensionOf(path);
  const SceneFormat* byExtension = nullptr;
  for (const SceneFormat& f : kFormats)
    if (ext == f.extension) byExtension = &f;

  if (!byExtension) {
    const std::string extension = ext.empty() ? "no file extension" : "extension '" + ext + "'";
    if (content != Content::Text)
      unsupported(path, std::string(describe(content)) + " content, " + extension);
    unsupported(path, extension);
  }
  if (content != byExtension->content && content != Content::Text) {
    // The bytes say another format than the name: believe the bytes, and say both.
    unsupported(path, std::string(describe(content)) + " content in a " + ext + " file");
  }
  if (content != byExtension->content && byExtension->content != Content::Text)
    unsupported(path, std::string(byExtension->name) +
                          " by its extension, but its first bytes are not " + byExtension->name);
  if (!byExtension->load) unsupported(path, byExtension->name);
  return byExtension->load(path, unreadable);
}

}  // namespace rad
