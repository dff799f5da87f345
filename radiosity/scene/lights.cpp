#include "radiosity/scene/lights.h"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/json_file.h"
#include "radiosity/scene/light_shapes.h"
#include "radiosity/scene/texture.h"

namespace rad {
namespace {

constexpr double kDegrees = M_PI / 180;
// The clear sky's sampling table: 1.4° texels, fine beside its circumsolar peak (e^(−3γ) halves
// in 13°).
constexpr int kClearSkyColumns = 256, kClearSkyRows = 128;

// A key as a JSON pointer token (RFC 6901): "~" → "~0", "/" → "~1".
std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

// Reads one light's values, each error naming the file, the line and the JSON pointer.
class LightReader {
 public:
  LightReader(const std::string& path, const std::string& text, const nlohmann::json& j,
              std::string pointer)
      : path_(path), text_(text), j_(j), pointer_(std::move(pointer)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const std::string at = key.empty() ? pointer_ : pointer_ + "/" + pointerToken(key);
    throw InputError(path_, lineOfPointer(text_, at), at + ": " + what);
  }

  void allowOnly(std::initializer_list<const char*> known) const {
    for (const auto& item : j_.items()) {
      bool ok = false;
      for (const char* k : known) ok = ok || item.key() == k;
      if (ok) continue;
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(item.key(), "unknown key \"" + item.key() + "\" for a " + j_["type"].get<std::string>() +
                           " light (known: " + list + ")");
    }
  }

  bool has(const std::string& key) const { return j_.contains(key); }
  const std::string& file() const { return path_; }

  const nlohmann::json& at(const std::string& key) const {
    if (!j_.contains(key)) fail("", "missing key \"" + key + "\"");
    return j_[key];
  }

  double number(const std::string& key) const {
    const auto& v = at(key);
    if (!v.is_number()) fail(key, "must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(key, "is not finite");
    return x;
  }

  Eigen::Vector3d vector(const std::string& key) const {
    const auto& v = at(key);
    if (!v.is_array() || v.size() != 3) fail(key, "must be an array of 3 numbers");
    Eigen::Vector3d out;
    for (int k = 0; k < 3; ++k) {
      if (!v[k].is_number()) fail(key, "must be an array of 3 numbers");
      out[k] = v[k].get<double>();
      if (!std::isfinite(out[k])) fail(key, "is not finite");
    }
    return out;
  }

  Eigen::Vector3d direction(const std::string& key) const {
    const Eigen::Vector3d d = vector(key);
    if (!(d.norm() > 0) || !std::isfinite(d.norm())) fail(key, "must be a non-zero direction");
    return d.normalized();
  }

  Rgb colour(const std::string& key) const {
    const Eigen::Vector3d v = vector(key);
    if (v.minCoeff() < 0) fail(key, "must not be negative");
    return {v.x(), v.y(), v.z()};
  }

 private:
  const std::string& path_;
  const std::string& text_;
  const nlohmann::json& j_;
  std::string pointer_;
};

Light readLight(const LightReader& r, const std::string& type) {
  Light light;
  if (type == "point") {
    r.allowOnly({"type", "position", "intensity", "group", "comment"});
    light.type = LightType::Point;
    light.position = r.vector("position");
    light.intensity = r.colour("intensity");
  } else if (type == "spot") {
    r.allowOnly({"type", "position", "direction", "intensity", "cone_degrees", "inner_cone_degrees",
                 "group", "comment"});
    light.type = LightType::Spot;
    light.position = r.vector("position");
    light.direction = r.direction("direction");
    light.intensity = r.colour("intensity");
    const double outer = r.number("cone_degrees");
    if (!(outer > 0 && outer <= 90)) r.fail("cone_degrees", "must be in (0, 90] degrees");
    const double inner = r.has("inner_cone_degrees") ? r.number("inner_cone_degrees") : outer;
    if (!(inner > 0 && inner <= 90)) r.fail("inner_cone_degrees", "must be in (0, 90] degrees");
    if (inner > outer)
      r.fail("inner_cone_degrees", "must not exceed cone_degrees (the outer half-angle)");
    light.cosOuter = std::cos(outer * kDegrees);
    light.cosInner = std::cos(inner * kDegrees);
  } else if (type == "directional") {
    r.allowOnly(
        {"type", "direction", "irradiance", "angular_diameter_degrees", "group", "comment"});
    light.type = LightType::Directional;
    light.direction = r.direction("direction");
    light.irradiance = r.colour("irradiance");
    if (r.has("angular_diameter_degrees")) {
      light.angularDiameterDegrees = r.number("angular_diameter_degrees");
      if (!(light.angularDiameterDegrees >= 0 && light.angularDiameterDegrees < 90))
        r.fail("angular_diameter_degrees", "must be in [0, 90) degrees");
    }
  } else if (type == "sky") {
    r.allowOnly({"type", "model", "radiance", "zenith_radiance", "sun_direction", "up", "group",
                 "comment"});
    light.type = LightType::Sky;
    std::string model = "uniform";
    if (r.has("model")) {
      if (!r.at("model").is_string())
        r.fail("model", "must be a string (uniform, cie_overcast, cie_clear)");
      model = r.at("model").get<std::string>();
    }
    // Each model names its one radiance for what it is: the sky's, or the zenith's.
    const char* key = "zenith_radiance";
    if (model == "cie_overcast") {
      light.skyModel = SkyModel::CieOvercast;
    } else if (model == "cie_clear") {
      light.skyModel = SkyModel::CieClear;
    } else if (model == "uniform") {
      key = "radiance";
    } else {
      r.fail("model",
             "unknown sky model \"" + model + "\" (known: uniform, cie_overcast, cie_clear)");
    }
    const char* other = model == "uniform" ? "zenith_radiance" : "radiance";
    if (r.has(other))
      r.fail(other, "a " + model + " sky takes \"" + key + "\", not \"" + other + "\"");
    light.radiance = r.colour(key);
    if (r.has("up")) light.up = r.direction("up");
    if (light.skyModel == SkyModel::CieClear) {
      const Eigen::Vector3d sun = r.direction("sun_direction");
      // The model describes a sky by day: the sun at or above the horizon.
      if (sun.dot(light.up) > 0)
        r.fail("sun_direction",
               "the sun must be above the horizon (sun_direction is the way its light travels: "
               "downwards, against up)");
      return cieClearSky(light.radiance, sun, light.up);
    }
    if (r.has("sun_direction"))
      r.fail("sun_direction", "only a cie_clear sky takes \"sun_direction\"");
  } else if (type == "environment") {
    r.allowOnly({"type", "file", "up", "scale", "group", "comment"});
    if (!r.at("file").is_string() || r.at("file").get<std::string>().empty())
      r.fail("file", "must be the image's file name (a non-empty string)");
    double scale = 1;
    if (r.has("scale")) {
      scale = r.number("scale");
      if (scale < 0) r.fail("scale", "must not be negative");
    }
    const Eigen::Vector3d up = r.has("up") ? r.direction("up") : Eigen::Vector3d(0, 1, 0);
    // Relative to the lights file, as a scene's textures are to their MTL.
    std::filesystem::path image(r.at("file").get<std::string>());
    if (image.is_relative()) image = std::filesystem::path(r.file()).parent_path() / image;
    std::error_code error;
    // Only a regular file: a device or a pipe named by mistake (or by a fuzzer) would never end.
    if (!std::filesystem::is_regular_file(image, error))
      r.fail("file", image.string() + ": cannot open the environment image");
    Texture texture;
    try {
      // Radiance HDR decodes to linear floats as stored; 8-bit images (PNG, JPEG, …) are
      // sRGB-encoded colour, decoded to linear like the scene's colour textures.
      texture = loadTextureFile(image.string(), TextureEncoding::Srgb);
    } catch (const InputError& e) {
      r.fail("file", std::string("environment image: ") + e.what());
    }
    return environmentLight(texture.width, texture.height,
                            EnvironmentMap::scaledTexels(texture, scale), up);
  } else {
    r.fail("type", "unknown light type \"" + type +
                       "\" (known: point, spot, directional, sky, environment)");
  }
  return light;
}

}  // namespace

std::string lightTypeName(LightType type) {
  switch (type) {
    case LightType::Point:
      return "point";
    case LightType::Spot:
      return "spot";
    case LightType::Directional:
      return "directional";
    case LightType::Sky:
      return "sky";
    case LightType::Environment:
      return "environment";
  }
  return "?";
}

std::vector<Light> loadLights(const std::string& path) {
  const JsonFile file = readJsonFile(path, "lights");
  const nlohmann::json& j = file.value;
  if (!j.is_object() || !j.contains("lights"))
    throw InputError(path, 1, "a lights file holds one JSON object with a \"lights\" array");
  for (const auto& item : j.items())
    if (item.key() != "lights" && item.key() != "comment")
      throw InputError(path, lineOfPointer(file.text, "/" + pointerToken(item.key())),
                       "/" + pointerToken(item.key()) + ": unknown key (known: lights, comment)");
  const nlohmann::json& list = j["lights"];
  if (!list.is_array())
    throw InputError(path, lineOfPointer(file.text, "/lights"), "/lights: must be an array");
  std::vector<Light> lights;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string pointer = "/lights/" + std::to_string(i);
    const LightReader reader(path, file.text, list[i], pointer);
    if (!list[i].is_object()) reader.fail("", "each light must be a JSON object");
    if (!list[i].contains("type") || !list[i]["type"].is_string())
      reader.fail("type",
                  "each light needs a \"type\" string (point, spot, directional, sky, "
                  "environment)");
    lights.push_back(readLight(reader, list[i]["type"].get<std::string>()));
    if (reader.has("group")) {
      const nlohmann::json& group = reader.at("group");
      if (!group.is_string() || group.get<std::string>().empty())
        reader.fail("group", "must be a light group's name (a non-empty string)");
      lights.back().group = group.get<std::string>();
    }
  }
  return lights;
}

std::string lightsSidecarPath(const std::string& scenePath) {
  return sidecarPath(scenePath, ".lights.json");
}

Light skyLight(const Rgb& radiance) {
  if (!radiance.isFinite() || radiance.minComponent() < 0)
    throw InputError("--sky: the radiance must be finite and not negative");
  Light light;
  light.type = LightType::Sky;
  light.radiance = radiance;
  light.group = "sky";
  return light;
}

Light sunLight(const Eigen::Vector3d& direction, const Rgb& irradiance) {
  if (!irradiance.isFinite() || irradiance.minComponent() < 0)
    throw InputError("--sun: the irradiance must be finite and not negative");
  if (!(direction.norm() > 0) || !std::isfinite(direction.norm()))
    throw InputError("--sun: the direction must be finite and non-zero");
  Light light;
  light.type = LightType::Directional;
  light.direction = direction.normalized();
  light.irradiance = irradiance;
  light.angularDiameterDegrees = 0.53;
  light.group = "sun";
  return light;
}

Light cieClearSky(const Rgb& zenithRadiance, const Eigen::Vector3d& sunTravel,
                  const Eigen::Vector3d& up) {
  Light light;
  light.type = LightType::Sky;
  light.skyModel = SkyModel::CieClear;
  light.radiance = zenithRadiance;
  light.direction = sunTravel.normalized();
  light.up = up.normalized();
  RAD_CHECK_MSG(light.direction.dot(light.up) <= 1e-12, "the clear sky's sun below the horizon");
  // Texel centres' values: the sampling only needs the shape; rows split at the horizon exactly
  // (an even count), so the ground rows are 0 and every direction above it has density.
  std::vector<Rgb> table(static_cast<std::size_t>(kClearSkyColumns) * kClearSkyRows);
  const EnvironmentMap frame(1, 1, {Rgb()}, light.up);
  for (int y = 0; y < kClearSkyRows; ++y)
    for (int x = 0; x < kClearSkyColumns; ++x) {
      const Eigen::Vector3d d =
          frame.direction((x + 0.5) / kClearSkyColumns, (y + 0.5) / kClearSkyRows);
      table[static_cast<std::size_t>(y) * kClearSkyColumns + x] =
          zenithRadiance * cieClearSkyRatio(d, -light.direction, light.up);
    }
  light.map =
      std::make_shared<EnvironmentMap>(kClearSkyColumns, kClearSkyRows, std::move(table), light.up);
  return light;
}

Light environmentLight(int width, int height, std::vector<Rgb> radiance,
                       const Eigen::Vector3d& up) {
  Light light;
  light.type = LightType::Environment;
  light.up = up.normalized();
  light.map = std::make_shared<EnvironmentMap>(width, height, std::move(radiance), light.up);
  return light;
}

Light scaledLight(const Light& light, const Rgb& scale) {
  Light scaled = light;
  scaled.intensity = light.intensity * scale;
  scaled.irradiance = light.irradiance * scale;
  scaled.radiance = light.radiance * scale;
  if (light.map) {
    std::vector<Rgb> texels = light.map->texels();
    for (Rgb& t : texels) t = t * scale;
    scaled.map = std::make_shared<EnvironmentMap>(light.map->width(), light.map->height(),
                                                  std::move(texels), light.map->up());
  }
  return scaled;
}

std::vector<Light> findSceneLights(const std::string& scenePath, const LightInput& input,
                                   bool log) {
  std::vector<Light> lights;
  std::string file = input.file;
  std::error_code error;
  if (file.empty() && std::filesystem::exists(lightsSidecarPath(scenePath), error))
    file = lightsSidecarPath(scenePath);
  if (!file.empty()) {
    lights = loadLights(file);
    if (log)
      logInfo("lights: " + std::to_string(lights.size()) + " from " + file +
              (input.file.empty() ? " (beside the scene)" : ""));
  }
  lights.insert(lights.end(), input.shortcuts.begin(), input.shortcuts.end());
  if (log && !input.shortcuts.empty())
    logInfo("lights: " + std::to_string(input.shortcuts.size()) + " from --sky/--sun");
  return lights;
}

}  // namespace rad
