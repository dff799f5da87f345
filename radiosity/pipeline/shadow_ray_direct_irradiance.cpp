#include "radiosity/pipeline/shadow_ray_direct_irradiance.h"

#include "radiosity/core/stream_tags.h"
#include "radiosity/pipeline/emitter_first_shot.h"
#include "radiosity/pipeline/solver_results.h"

namespace rad {

std::vector<Rgb> directIrradianceByShadowRays(const Solution& solution,
                                              const RadiosityProblem& problem,
                                              const std::vector<Rgb>& lightsIrradiance,
                                              const RayCaster& rays,
                                              const ElementExposure& exposure,
                                              const SolveOptions& options, uint64_t& raysCast) {
  const int n = solution.mesh->elementCount();
  RadiosityProblem own = problem;
  own.emission = ownEmission(solution, problem, lightsIrradiance);
  EmitterFirstShot shot(*solution.mesh, rays, exposure, options.seed ^ stream_tag::kSplitDirect,
                        EmitterFirstShot::raysForSolve(options.raysPerElement),
                        /*largeEmitterShare=*/1.0);
  shot.apply(own);
  raysCast += shot.raysCast();
  std::vector<Rgb> direct = shot.active() ? shot.irradiance() : std::vector<Rgb>(n);
  for (int e = 0; e < n; ++e) {
    if (!lightsIrradiance.empty()) direct[e] += lightsIrradiance[e];
    if (problem.reflectance[e].maxComponent() <= 0) direct[e] = Rgb();
  }
  return direct;
}

}  // namespace rad
