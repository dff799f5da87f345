#pragma once

// The camera a render is made from: --camera FILE, else the scene's sidecar (<scene>.camera.json),
// else a glTF scene's own camera, with command-line overrides. render binds every override,
// compare the image size only; resolveCamera is the one look-up for both.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/render/camera.h"

namespace rad {

struct CameraOptions {
  std::string file;                          // --camera; empty: the sidecar or the scene's own
  std::vector<double> position, lookAt, up;  // empty: not given
  std::optional<double> vfov, lensRadius, focusDistance;
  std::optional<int> width, height;
  bool placeable = false;  // --position and --look-at are bound: they can stand for a file
};

enum class CameraOverrides { All, SizeOnly };

// Binds --camera and the overrides `which` names.
void addCameraOptions(CLI::App& command, CameraOptions& options, CameraOverrides which);

struct ResolvedCamera {
  Camera camera;
  std::string file;  // the camera file read ("" for none), which also holds the motion blur
};

// The camera for `scenePath`, checked (validateCamera); InputError naming the scene when there is
// none, naming the file when it is bad, and for --focus-distance on a pinhole camera.
ResolvedCamera resolveCamera(const CameraOptions& options, const std::string& scenePath);

}  // namespace rad
