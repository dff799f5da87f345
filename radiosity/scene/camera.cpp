#include "radiosity/scene/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "radiosity/core/errors.h"
#include "radiosity/scene/gltf_loader.h"
#include "radiosity/scene/json_file.h"

namespace rad {
namespace {

Eigen::Vector3d readVector(const nlohmann::json& j, const std::string& key,
                           const std::string& file) {
  const auto& v = j.at(key);
  if (!v.is_array() || v.size() != 3)
    throw InputError(file, 0, "\"" + key + "\" must be an array of 3 numbers");
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    if (!v[k].is_number())
      throw InputError(file, 0, "\"" + key + "\" must be an array of 3 numbers");
    out[k] = v[k].get<double>();
    if (!std::isfinite(out[k])) throw InputError(file, 0, "\"" + key + "\" is not finite");
  }
  return out;
}

double readNumber(const nlohmann::json& j, const std::string& key, const std::string& file) {
  const auto& v = j.at(key);
  if (!v.is_number()) throw InputError(file, 0, "\"" + key + "\" must be a number");
  return v.get<double>();
}

int readInt(const nlohmann::json& j, const std::string& key, const std::string& file) {
  const auto& v = j.at(key);
  if (!v.is_number_integer()) throw InputError(file, 0, "\"" + key + "\" must be an integer");
  return v.get<int>();
}

}  // namespace

void validateCamera(const Camera& c, const std::string& source) {
  const Eigen::Vector3d forward = c.lookAt - c.position;
  if (!(forward.norm() > 0)) throw InputError(source, 0, "camera look_at equals its position");
  if (!(c.up.norm() > 0) || forward.normalized().cross(c.up.normalized()).norm() < 1e-9)
    throw InputError(source, 0,
                     "camera up must be non-zero and not parallel to the view direction");
  if (!(c.vfovDegrees > 0 && c.vfovDegrees < 180))
    throw InputError(source, 0, "vertical field of view must be in (0, 180) degrees");
  if (c.width <= 0 || c.height <= 0 || c.width > 16384 || c.height > 16384)
    throw InputError(source, 0, "image width and height must be in 1..16384");
  if (!(c.lensRadius >= 0) || !std::isfinite(c.lensRadius))
    throw InputError(source, 0, "lens radius must be >= 0");
  if (c.lensRadius > 0 && !(c.focusDistance > 0))
    throw InputError(source, 0, "a lens radius > 0 needs a focus distance > 0");
}

std::string cameraSidecarPath(const std::string& scenePath) {
  return sidecarPath(scenePath, ".camera.json");
}

Camera loadCamera(const std::string& path) {
  const JsonFile file = readJsonFile(path);
  const nlohmann::json& j = file.value;
  if (!j.is_object()) throw InputError(path, 1, "a camera file holds one JSON object");
  static const char* known[] = {"position", "look_at", "up", "vfov_degrees", "width", "height",
                                "lens_radius", "focus_distance", "comment",
                                // motion blur for --method distribution: read by loadMotionSpec
                                "shutter", "motion"};
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* k : known) ok = ok || item.key() == k;
    if (!ok) {
      // nlohmann keeps no positions: the key's first appearance in the text is its line.
      const size_t at = file.text.find("\"" + item.key() + "\"");
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      throw InputError(path, at == std::string::npos ? 0 : lineOfByte(file.text, at),
                       "unknown camera key \"" + item.key() + "\" (known: " + list + ")");
    }
  }
  for (const char* key : {"position", "look_at", "up", "vfov_degrees", "width", "height"})
    if (!j.contains(key))
      throw InputError(path, 0, std::string("missing camera key \"") + key + "\"");
  Camera c;
  c.position = readVector(j, "position", path);
  c.lookAt = readVector(j, "look_at", path);
  c.up = readVector(j, "up", path);
  c.vfovDegrees = readNumber(j, "vfov_degrees", path);
  c.width = readInt(j, "width", path);
  c.height = readInt(j, "height", path);
  if (j.contains("lens_radius")) c.lensRadius = readNumber(j, "lens_radius", path);
  if (j.contains("focus_distance")) c.focusDistance = readNumber(j, "focus_distance", path);
  validateCamera(c, path);
  return c;
}

std::optional<Camera> findSceneCamera(const std::string& scenePath) {
  const std::string path = cameraSidecarPath(scenePath);
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    // A glTF scene may carry its own camera; the sidecar, when there is one, overrides it.
    std::string ext = std::filesystem::path(scenePath).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".gltf" || ext == ".glb") return loadGltfCamera(scenePath);
    return std::nullopt;
  }
  return loadCamera(path);
}

}  // namespace rad
