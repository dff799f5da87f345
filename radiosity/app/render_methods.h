#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/integrator.h"

namespace rad {

// What a method's integrator is built from.
struct MethodInputs {
  const RenderScene& scene;
  const std::vector<Rgb>* radiosity = nullptr;  // B per element, for methods that need the solve
  int gather = 64;                              // final-gather rays per diffuse eye hit
};

// One way to solve the rendering equation for an image, and the light paths it captures in
// Heckbert's notation (L light, D diffuse, S specular, E eye). `render --method` and `compare`
// both read this table: adding a method is one entry.
struct RenderMethod {
  std::string name;
  std::string paths;        // Heckbert expression of the paths it captures
  std::string summary;      // one line for --help and the contact sheet
  bool needsSolve = false;  // runs the radiosity solve first
  bool usesMotion = false;  // renders the sidecar's "motion" (motion blur)
  int defaultSpp = 4;
  std::function<std::unique_ptr<Integrator>(const MethodInputs&)> makeIntegrator;
};

const std::vector<RenderMethod>& renderMethods();
// Throws InputError naming the known methods when `name` is none of them.
const RenderMethod& findRenderMethod(const std::string& name);
// "direct | whitted | ...", for help texts and errors.
std::string renderMethodNames();
// One line per method: "name (paths, N spp): summary", for --help.
std::string renderMethodHelp();

}  // namespace rad
