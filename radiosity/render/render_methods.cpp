#include "radiosity/render/render_methods.h"

#include "radiosity/core/errors.h"
#include "radiosity/render/direct_lighting.h"
#include "radiosity/render/distribution_ray_tracer.h"
#include "radiosity/render/path_renderer.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/render/radiosity_integrator.h"
#include "radiosity/render/whitted_ray_tracer.h"

namespace rad {

const std::vector<RenderMethod>& renderMethods() {
  static const std::vector<RenderMethod> methods = {
      {"direct", "LD?E", "OpenGL local model: point lights at the emitters' centres, no shadows",
       false, false, 4,
       [](const MethodInputs& in) { return std::make_unique<DirectLighting>(in.scene); }},
      {"whitted", "LD?S*E",
       "Whitted ray tracing: shadow rays to point lights, recursive mirror and glass", false, false,
       4, [](const MethodInputs& in) { return std::make_unique<WhittedRayTracer>(in.scene); }},
      {"distribution", "LD?S*E",
       "distribution ray tracing: area lights, glossy (S), depth of field, motion blur", false,
       true, 64,
       [](const MethodInputs& in) { return std::make_unique<DistributionRayTracer>(in.scene); }},
      {"path", "L(D|S)*E", "Monte Carlo path tracing with next-event estimation", false, false, 64,
       [](const MethodInputs& in) { return std::make_unique<PathTracer>(in.scene); }},
      {"bdpt", "L(D|S)*E",
       "bidirectional path tracing: eye and light sub-paths joined, MIS, light tracing", false,
       false, 64,
       [](const MethodInputs& in) {
         BdptOptions options;
         options.heuristic = in.mis;
         return std::make_unique<Bdpt>(in.scene, *in.camera, options);
       }},
      {"radiosity", "L(D|S)*E", "radiosity solution (LD*) with final gather and specular chains",
       true, false, 16,
       [](const MethodInputs& in) {
         return makeRadiosityIntegrator(in.scene, *in.radiosity, *in.directIrradiance, in.gather);
       }},
  };
  return methods;
}

std::string renderMethodNames() {
  std::string names;
  for (const RenderMethod& m : renderMethods()) names += (names.empty() ? "" : " | ") + m.name;
  return names;
}

std::string renderMethodHelp() {
  std::string help = "Rendering method:";
  for (const RenderMethod& m : renderMethods())
    help += "\n  " + m.name + " (" + m.paths + ", default " + std::to_string(m.defaultSpp) +
            " spp): " + m.summary;
  return help;
}

RenderOutput renderMethodImage(const Camera& camera, const Integrator& integrator,
                               const RenderSettings& settings) {
  if (const auto* paths = dynamic_cast<const PathIntegrator*>(&integrator))
    return std::move(renderPathImage(camera, *paths, settings, nullptr).full);
  return renderImage(camera, integrator, settings);
}

const RenderMethod& findRenderMethod(const std::string& name) {
  for (const RenderMethod& m : renderMethods())
    if (m.name == name) return m;
  throw InputError("unknown --method '" + name + "' (expected " + renderMethodNames() + ")");
}

}  // namespace rad
