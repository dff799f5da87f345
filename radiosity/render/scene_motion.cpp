#include "radiosity/render/scene_motion.h"

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "radiosity/core/errors.h"
#include "radiosity/scene/json_file.h"

namespace rad {
namespace {

// nlohmann keeps no positions once parsed: find the n-th occurrence of "key" after `from` in the
// text instead. Good enough to point a person at the right line of a hand-written sidecar.
size_t findKey(const std::string& text, const std::string& key, size_t from, int nth = 0) {
  size_t at = from;
  for (int k = 0; k <= nth; ++k) {
    at = text.find("\"" + key + "\"", k == 0 ? at : at + 1);
    if (at == std::string::npos) return from;
  }
  return at;
}

}  // namespace

MotionSpec loadMotionSpec(const std::string& path) {
  const JsonFile file = readJsonFile(path);
  const std::string& text = file.text;
  const nlohmann::json& j = file.value;
  MotionSpec spec;
  spec.source = path;
  if (!j.is_object()) return spec;  // loadCamera reports this

  if (j.contains("shutter")) {
    const int line = lineOfByte(text, findKey(text, "shutter", 0));
    const auto& s = j["shutter"];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number())
      throw InputError(path, line, "\"shutter\" must be [open, close], two numbers (seconds)");
    spec.shutterOpen = s[0].get<double>();
    spec.shutterClose = s[1].get<double>();
    if (!std::isfinite(spec.shutterOpen) || !std::isfinite(spec.shutterClose) ||
        !(spec.shutterClose >= spec.shutterOpen))
      throw InputError(path, line, "\"shutter\": need finite open <= close");
  }
  if (!j.contains("motion")) return spec;
  const size_t motionAt = findKey(text, "motion", 0);
  const auto& list = j["motion"];
  if (!list.is_array())
    throw InputError(path, lineOfByte(text, motionAt),
                     "\"motion\" must be an array of {\"object\": name, \"velocity\": [x, y, z]}");
  std::map<std::string, int> seen;
  for (size_t i = 0; i < list.size(); ++i) {
    const auto& entry = list[i];
    MotionSpec::Object object;
    object.line = lineOfByte(text, findKey(text, "object", motionAt, static_cast<int>(i)));
    const std::string where = "\"motion\" entry " + std::to_string(i + 1);
    if (!entry.is_object())
      throw InputError(path, lineOfByte(text, motionAt),
                       where + " must be {\"object\": name, \"velocity\": [x, y, z]}");
    for (const auto& item : entry.items())
      if (item.key() != "object" && item.key() != "velocity")
        throw InputError(path, object.line, where + ": unknown key \"" + item.key() + "\"");
    if (!entry.contains("object") || !entry["object"].is_string() ||
        entry["object"].get<std::string>().empty())
      throw InputError(path, object.line, where + ": \"object\" must name an OBJ o/g group");
    object.name = entry["object"].get<std::string>();
    const auto& v = entry.contains("velocity") ? entry["velocity"] : nlohmann::json();
    if (!v.is_array() || v.size() != 3)
      throw InputError(path, object.line,
                       where + " ('" + object.name + "'): \"velocity\" must be [x, y, z]");
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number() || !std::isfinite(v[k].get<double>()))
        throw InputError(path, object.line,
                         where + " ('" + object.name + "'): \"velocity\" needs 3 finite numbers");
      object.velocity[k] = v[k].get<double>();
    }
    if (seen.count(object.name))
      throw InputError(path, object.line,
                       where + ": object '" + object.name + "' already moves (entry " +
                           std::to_string(seen[object.name]) + ")");
    seen[object.name] = static_cast<int>(i + 1);
    spec.objects.push_back(object);
  }
  return spec;
}

SceneMotion::SceneMotion(const Scene& scene, const PatchMesh& mesh, const MotionSpec& spec) {
  // Velocity per input polygon (= patch), from its group's name.
  std::vector<Eigen::Vector3d> polygonVelocity(scene.polygons.size(), Eigen::Vector3d::Zero());
  std::vector<int> polygonEntry(scene.polygons.size(), -1);
  for (size_t k = 0; k < spec.objects.size(); ++k) {
    const MotionSpec::Object& object = spec.objects[k];
    int faces = 0;
    for (size_t p = 0; p < scene.polygons.size(); ++p) {
      if (scene.polygons[p].object != object.name) continue;
      ++faces;
      if (scene.materials[scene.polygons[p].material].isEmitter())
        throw InputError(spec.source, object.line,
                         "object '" + object.name + "' emits light (face at " + scene.sourcePath +
                             ":" + std::to_string(scene.polygons[p].sourceLine) +
                             "); moving emitters are not supported");
      polygonVelocity[p] = object.velocity;
      polygonEntry[p] = static_cast<int>(k);
    }
    if (faces == 0)
      throw InputError(
          spec.source, object.line,
          "object '" + object.name + "' is no 'o' or 'g' group of " + scene.sourcePath);
  }

  const int nv = mesh.vertexCount(), ne = mesh.elementCount();
  const double open = spec.shutterOpen, close = spec.shutterClose;
  vertices_.open.assign(nv, Eigen::Vector3d::Zero());
  vertices_.close.assign(nv, Eigen::Vector3d::Zero());
  elementOpen_.assign(ne, Eigen::Vector3d::Zero());
  elementClose_.assign(ne, Eigen::Vector3d::Zero());
  std::vector<int> vertexEntry(nv, -2);  // -2: not seen yet, -1: static, k: motion entry k
  for (int e = 0; e < ne; ++e) {
    const int patch = mesh.patch(e);
    const int entry = polygonEntry[patch];
    const Eigen::Vector3d v = polygonVelocity[patch];
    elementOpen_[e] = v * open;
    elementClose_[e] = v * close;
    if (entry >= 0) ++movingElements_;
    for (int corner : mesh.cornerVertices(e)) {
      if (vertexEntry[corner] == -2) {
        vertexEntry[corner] = entry;
        vertices_.open[corner] = v * open;
        vertices_.close[corner] = v * close;
      } else if (vertexEntry[corner] != entry) {
        const int moving = entry >= 0 ? entry : vertexEntry[corner];
        throw InputError(spec.source, spec.objects[moving].line,
                         "object '" + spec.objects[moving].name +
                             "' shares vertices with geometry that moves differently (face at " +
                             scene.sourcePath + ":" +
                             std::to_string(scene.polygons[patch].sourceLine) +
                             "); give it vertices of its own");
      }
    }
  }
}

}  // namespace rad
