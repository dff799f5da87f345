#include "viewer/scene_camera.h"

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

Eigen::Vector3d vector3(const nlohmann::json& j, const std::string& key, const std::string& path) {
  if (!j.contains(key)) throw InputError(path, 0, "missing key '" + key + "'");
  const nlohmann::json& v = j.at(key);
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw InputError(path, 0, "'" + key + "' must be an array of three numbers");
  Eigen::Vector3d out(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  if (!out.allFinite()) throw InputError(path, 0, "'" + key + "' is not finite");
  return out;
}

}  // namespace

std::string viewCameraFile(const std::string& scenePath) {
  std::filesystem::path p(scenePath);
  return (p.parent_path() / (p.stem().string() + ".camera.json")).string();
}

std::optional<CameraSpec> readCameraSidecar(const std::string& scenePath) {
  const std::string path = viewCameraFile(scenePath);
  if (!std::filesystem::is_regular_file(path)) return std::nullopt;
  std::ifstream in(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number too large for a double (e.g. 1e400).
    throw InputError(path, 0, std::string("malformed JSON: ") + e.what());
  }
  if (!j.is_object()) throw InputError(path, 0, "expected a JSON object");
  CameraSpec c;
  c.position = vector3(j, "position", path);
  c.lookAt = vector3(j, "look_at", path);
  c.up = vector3(j, "up", path);
  if (!j.contains("vfov_degrees") || !j["vfov_degrees"].is_number())
    throw InputError(path, 0, "missing or non-numeric 'vfov_degrees'");
  c.vfovDegrees = j["vfov_degrees"].get<double>();
  if (!(c.vfovDegrees > 0 && c.vfovDegrees < 180))
    throw InputError(path, 0, "'vfov_degrees' must lie in (0, 180)");
  const Eigen::Vector3d forward = c.lookAt - c.position;
  if (!(forward.norm() > 0)) throw InputError(path, 0, "'look_at' equals 'position'");
  if (!(forward.normalized().cross(c.up).norm() > 1e-6))
    throw InputError(path, 0, "'up' is zero or parallel to the view direction");
  return c;
}

CameraSpec frameBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max,
                       const Eigen::Vector3d& direction, double aspect, double vfovDegrees) {
  CameraSpec c;
  c.vfovDegrees = vfovDegrees;
  const Eigen::Vector3d d = direction.normalized();
  const Eigen::Vector3d centre = 0.5 * (min + max);
  const double radius = std::max(0.5 * (max - min).norm(), 1e-12);
  // The sphere must fit the narrower of the two fields of view.
  const double half = 0.5 * vfovDegrees * M_PI / 180;
  const double halfNarrow = aspect < 1 ? std::atan(std::tan(half) * aspect) : half;
  const double distance = radius / std::sin(halfNarrow);
  c.lookAt = centre;
  c.position = centre - distance * d;
  c.up = std::abs(d.y()) > 0.9 ? Eigen::Vector3d(0, 0, 1) : Eigen::Vector3d(0, 1, 0);
  return c;
}

}  // namespace rad
