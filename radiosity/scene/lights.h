#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"

namespace rad {

// Lights besides emissive polygons. Units: point and spot intensity in W·sr⁻¹; directional
// irradiance in W·m⁻² on a surface facing the light; sky radiance in W·m⁻²·sr⁻¹ over the upper
// hemisphere of `up` (rays that leave the scene below the horizon see black ground).
enum class LightType { Point, Spot, Directional, Sky };
// The sky's radiance over its hemisphere: uniform, or the CIE standard overcast sky
// L(θ) = L_zenith (1 + 2 cos θ) / 3 (θ from the zenith `up`; Moon and Spencer 1942).
enum class SkyModel { Uniform, CieOvercast };
std::string lightTypeName(LightType type);  // "point", "spot", "directional", "sky"

struct Light {
  LightType type = LightType::Point;
  Eigen::Vector3d position{0, 0, 0};      // point, spot
  Eigen::Vector3d direction{0, -1, 0};    // spot axis, directional travel; unit length
  Eigen::Vector3d up{0, 1, 0};            // sky: the zenith; unit length
  Rgb intensity;                          // point, spot: W·sr⁻¹
  Rgb irradiance;                         // directional: W·m⁻² on a surface facing it
  Rgb radiance;                           // sky: W·m⁻²·sr⁻¹ (CIE overcast: at the zenith)
  SkyModel skyModel = SkyModel::Uniform;  // sky
  double cosOuter = 0, cosInner = 0;      // spot: cosines of the outer and inner half-angles
  double angularDiameterDegrees = 0;      // directional: 0 a hard sun; the sun is about 0.53
};

// Reads a lights file: {"lights": [{"type": "point"|"spot"|"directional"|"sky", ...}, ...]}
// (see docs/physics.md). Throws InputError naming the file, the line and the JSON pointer of the
// bad value (e.g. "/lights/2/intensity"): unknown types ("environment" is not supported yet),
// unknown or missing keys, unknown sky models, negative or non-finite values, zero-length
// directions, cone angles outside (0, 90], inner cone wider than the outer, angular diameter
// outside [0, 90).
std::vector<Light> loadLights(const std::string& path);

// `<scene without its extension>.lights.json`: the lights that ship next to a scene.
std::string lightsSidecarPath(const std::string& scenePath);

// The shortcuts of the command line, checked as the file's values are (InputError naming the
// option): a uniform sky with up +y, and a sun of angular diameter 0.53°.
Light skyLight(const Rgb& radiance);
Light sunLight(const Eigen::Vector3d& direction, const Rgb& irradiance);

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
