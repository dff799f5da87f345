#include "radiosity/pipeline/kept_factors_stage.h"

#include "radiosity/core/check.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/scene/light_groups.h"

namespace rad {

std::vector<Rgb> keptLightsIrradiance(const KeptFactors& kept, const std::vector<Rgb>& scale) {
  RAD_CHECK(scale.empty() || scale.size() == kept.lightIrradiance.size());
  std::vector<Rgb> sum;
  for (size_t l = 0; l < kept.lightIrradiance.size(); ++l) {
    const std::vector<Rgb>& light = kept.lightIrradiance[l];
    sum.resize(light.size());
    for (size_t e = 0; e < light.size(); ++e)
      sum[e] += scale.empty() ? light[e] : scale[l] * light[e];
  }
  return sum;
}

std::shared_ptr<KeptFactors> keepLightsApart(Solution& solution, const RayCaster& rays,
                                             const SolveOptions& options,
                                             const ElementExposure& exposure, double elementEdge,
                                             std::vector<int>& rayMultipliers, SolveReport& report,
                                             const std::vector<KnownIrradiance>* known) {
  RAD_CHECK(!known || known->size() == solution.scene.lights.size());
  const Scene& scene = solution.scene;
  const PatchMesh& mesh = *solution.mesh;
  auto kept = std::make_shared<KeptFactors>();
  kept->scenePath = options.scenePath;
  kept->fingerprint = keptFactorsFingerprint(scene, options);
  kept->options = options;
  kept->area = solution.problem.area;
  kept->elementEdge = elementEdge;
  std::vector<std::vector<Rgb>> sources;
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    if (!scene.materials[m].isEmitter()) continue;
    std::vector<Rgb>& power = sources.emplace_back(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e)
      if (mesh.material(e) == static_cast<int>(m)) power[e] = solution.problem.emission[e];
  }
  uint64_t lightRays = 0;
  const std::vector<LightGroup> groups = lightGroups(scene);
  kept->lightGroups.resize(scene.lights.size());
  for (const LightGroup& g : groups)
    for (size_t l : g.lights) kept->lightGroups[l] = g.name;
  for (size_t l = 0; l < scene.lights.size(); ++l) {
    const std::vector<size_t> one{l};
    DirectLightStage stage(scene, mesh, rays, options, &exposure, &one);
    stage.apply(solution.problem, known ? &(*known)[l] : nullptr);
    kept->lightTypes.push_back(lightTypeName(scene.lights[l].type));
    kept->lightIrradiance.push_back(stage.irradiance());
    sources.push_back(stage.irradiance());
    lightRays += stage.raysCast();
  }
  report.directLightRays = lightRays;
  rayMultipliers = sourceRayMultipliers(solution.problem.area, sources);
  kept->lightInput = options.lights;
  kept->lightsFingerprint = keptLightsFingerprint(scene.lights);
  kept->materialsFingerprint = keptMaterialsFingerprint(scene);
  kept->materialVisibility = keptMaterialVisibility(scene);
  kept->rayMultiplier = rayMultipliers;
  for (int e = 0; e < mesh.elementCount(); ++e) {
    kept->corners.push_back(mesh.corners(e));
    kept->material.push_back(mesh.material(e));
    kept->patch.push_back(mesh.patch(e));
  }
  return kept;
}

SolveOptions withSolverOf(SolveOptions kept, const SolveOptions& solver) {
  kept.solver = solver.solver;
  kept.tolerance = solver.tolerance;
  kept.maxIterations = solver.maxIterations;
  kept.threads = solver.threads;
  kept.timeLimit = solver.timeLimit;
  kept.outputDir = solver.outputDir;
  return kept;
}

}  // namespace rad
