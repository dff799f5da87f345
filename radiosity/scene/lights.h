#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/scene/environment_map.h"

namespace rad {

// Lights besides emissive polygons. Units: point and spot intensity in W·sr⁻¹; directional
// irradiance in W·m⁻² on a surface facing the light; sky radiance in W·m⁻²·sr⁻¹ over the upper
// hemisphere of `up` (rays that leave the scene below the horizon see black ground); environment
// radiance in W·m⁻²·sr⁻¹ over the whole sphere, from an image (environment_map.h).
enum class LightType { Point, Spot, Directional, Sky, Environment };
// The sky's radiance over its hemisphere: uniform; the CIE standard overcast sky
// L(θ) = L_zenith (1 + 2 cos θ) / 3 (θ from the zenith `up`; Moon and Spencer 1942); or the CIE
// standard clear sky (CIE S 011/E:2003 type 12, Kittler's clear sky) around the sun
// −`direction` (light_shapes.h).
enum class SkyModel { Uniform, CieOvercast, CieClear };
// "point", "spot", "directional", "sky", "environment"
std::string lightTypeName(LightType type);

struct Light {
  LightType type = LightType::Point;
  Eigen::Vector3d position{0, 0, 0};      // point, spot
  Eigen::Vector3d direction{0, -1, 0};    // spot axis, directional and clear sky's sun travel
  Eigen::Vector3d up{0, 1, 0};            // sky, environment: the zenith; unit length
  Rgb intensity;                          // point, spot: W·sr⁻¹
  Rgb irradiance;                         // directional: W·m⁻² on a surface facing it
  Rgb radiance;                           // sky: W·m⁻²·sr⁻¹ (CIE models: at the zenith)
  SkyModel skyModel = SkyModel::Uniform;  // sky
  double cosOuter = 0, cosInner = 0;      // spot: cosines of the outer and inner half-angles
  double angularDiameterDegrees = 0;      // directional: 0 a hard sun; the sun is about 0.53
  // Environment: its image (radiance × scale). CIE clear sky: the formula tabulated, which the
  // solve and the renders sample by and the local model integrates (cieClearSky builds it).
  std::shared_ptr<const EnvironmentMap> map;
  // Its light group (bake --light-groups, scene/light_groups.h): the lights file's "group", a
  // glTF light's name, "sky" / "sun" for the shortcuts; empty: a group of its own.
  std::string group;
};

// Reads a lights file: {"lights": [{"type": "point"|"spot"|"directional"|"sky"|"environment",
// ...}, ...]} (see docs/physics.md). Throws InputError naming the file, the line and the JSON
// pointer of the bad value (e.g. "/lights/2/intensity"): unknown types, unknown or missing keys,
// unknown sky models, negative or non-finite values, zero-length directions, cone angles outside
// (0, 90], inner cone wider than the outer, angular diameter outside [0, 90), a clear sky's sun
// below the horizon, an environment image that cannot be read (its path relative to the lights
// file).
std::vector<Light> loadLights(const std::string& path);

// `<scene without its extension>.lights.json`: the lights that ship next to a scene.
std::string lightsSidecarPath(const std::string& scenePath);

// The shortcuts of the command line, checked as the file's values are (InputError naming the
// option): a uniform sky with up +y, and a sun of angular diameter 0.53°.
Light skyLight(const Rgb& radiance);
Light sunLight(const Eigen::Vector3d& direction, const Rgb& irradiance);

// A CIE clear sky of zenith radiance `zenithRadiance`, its sun towards −`sunTravel`, with its
// sampling table (`map`). Directions: unit; the sun at or above the horizon (RAD_CHECKed).
Light cieClearSky(const Rgb& zenithRadiance, const Eigen::Vector3d& sunTravel,
                  const Eigen::Vector3d& up = {0, 1, 0});
// An environment light of `width` × `height` radiance values (rows top first; environment_map.h).
Light environmentLight(int width, int height, std::vector<Rgb> radiance,
                       const Eigen::Vector3d& up = {0, 1, 0});

// `light` with its strength multiplied by `scale` per channel (relight's light overrides): the
// intensity, irradiance or radiance, and an environment's or clear sky's texels.
Light scaledLight(const Light& light, const Rgb& scale);

// Where a scene's lights come from: a lights file (`file`; when empty, the sidecar beside the
// scene if it exists) plus the command line's shortcuts.
struct LightInput {
  std::string file;
  std::vector<Light> shortcuts;
};

// The lights of `scenePath` as `input` says; logs where they came from when `log`.
std::vector<Light> findSceneLights(const std::string& scenePath, const LightInput& input,
                                   bool log = true);

}  // namespace rad
