#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/bdpt.h"
#include "radiosity/render/camera.h"
#include "radiosity/render/final_gather_options.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/integrator.h"

namespace rad {

// Render's gather default: one shadow and one gather ray per pixel sample, which the sampler
// stratifies across the pixel's samples. (The solve takes `solve`'s defaults, so that a render can
// reuse what `solve` wrote.)
constexpr int kRenderGather = 1;

// What a method's integrator is built from.
struct MethodInputs {
  const RenderScene& scene;
  const std::vector<Rgb>* radiosity = nullptr;  // B per element, for methods that need the solve
  // E_d per element as the solve computed it, with `radiosity` (the split's indirect part).
  const std::vector<Rgb>* directIrradiance = nullptr;
  // The rays per diffuse eye hit of the pass over the solution (radiosity:
  // makeRadiosityIntegrator).
  FinalGatherOptions gather = {kRenderGather, 0};
  const Camera* camera = nullptr;          // bdpt: light tracing connects to the camera
  MisHeuristic mis = MisHeuristic::Power;  // bdpt
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

// Renders an image with a method's integrator: integrators that follow whole light paths go
// through the path renderer (bdpt's light tracing adds to other pixels), the others through
// renderImage. The same samples either way.
RenderOutput renderMethodImage(const Camera& camera, const Integrator& integrator,
                               const RenderSettings& settings);

}  // namespace rad
