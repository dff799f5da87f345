#include "radiosity/pipeline/relight.h"

#include <chrono>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/kept_factors_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/solve_stages.h"
#include "radiosity/pipeline/solver_results.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/scene/two_sided.h"
#include "radiosity/solvers/solver_factory.h"

namespace rad {

namespace {

// Refuses a scene that no longer fits the kept solve: other geometry or mesh options (the
// fingerprint), or other lights, whose first shot is kept.
void checkKeptSceneFits(const KeptFactors& header, const std::string& keptPath,
                        const Scene& scene) {
  if (keptFactorsFingerprint(scene, header.options) != header.fingerprint)
    throw InputError(keptPath, 0,
                     "the scene " + header.scenePath +
                         " changed since `solve --keep-factors` (its geometry, UVs, cut-outs, "
                         "mirrors or glass, or the mesh options): relight reuses rays that no "
                         "longer fit it; solve again");
  if (scene.lights.size() != header.lightTypes.size())
    throw InputError(keptPath, 0,
                     "the scene has " + std::to_string(scene.lights.size()) +
                         " light(s) now, the kept solve had " +
                         std::to_string(header.lightTypes.size()) +
                         ": relight changes lights' strengths (--override), not their number; "
                         "solve again");
  if (!header.lightsFingerprint.empty() &&
      keptLightsFingerprint(scene.lights) != header.lightsFingerprint)
    throw InputError(keptPath, 0,
                     "the lights changed since `solve --keep-factors` (where they are, their "
                     "shape or strength in the lights file or the --sky/--sun options): relight "
                     "reuses their first shot; scale their strength with --override, or solve "
                     "again");
}

// The lights' first shot from the kept E_d: E += Σ_l ρ scale_l E_d,l, no ray cast.
void addKeptFirstShot(const KeptFactors& kept, const std::vector<Rgb>& lightScale,
                      RadiosityProblem& problem) {
  for (size_t l = 0; l < kept.lightIrradiance.size(); ++l)
    for (int e = 0; e < problem.size(); ++e)
      problem.emission[e] += problem.reflectance[e] * lightScale[l] * kept.lightIrradiance[l][e];
}

}  // namespace

Scene loadKeptScene(const KeptFactors& kept) {
  // With the scene's own lights (glTF), as solved; a texture the solve could not read falls back
  // to its material's colour here too.
  Scene scene = loadScene(kept.scenePath, UnreadableTextures::UseMaterialColour);
  for (Light& light : findSceneLights(kept.scenePath, kept.lightInput, false))
    scene.lights.push_back(std::move(light));
  applyTwoSidedInput(scene, kept.options.twoSided);
  addBackSides(scene);
  return scene;
}

RelightStart startRelight(const KeptFactors& header, const std::string& keptPath, Scene scene,
                          const SolveOptions& solverOptions) {
  RelightStart started;
  started.start = std::chrono::steady_clock::now();
  started.options = withSolverOf(header.options, solverOptions);
  const SolveOptions& options = started.options;
  validateSolveOptions(options);
  checkKeptSceneFits(header, keptPath, scene);
  Solution& solution = started.result.solution;
  SolveReport& report = started.result.report;
  const ThreadLimit threads = limitSolveThreads(options, report);
  solution.scene = std::move(scene);
  meshStage(solution, options, report);
  // E and ρ from the materials as they are now (the lights' first shot is added from the kept
  // E_d when the rows are in).
  solution.problem = makeProblem(solution.scene, *solution.mesh, nullptr);
  return started;
}

SolveResult finishRelight(RelightStart started, KeptFactors kept, const std::string& keptPath,
                          const std::vector<Rgb>& lightScale) {
  RAD_CHECK_EQ(lightScale.size(), kept.lightIrradiance.size());
  const SolveOptions& options = started.options;
  SolveResult result = std::move(started.result);
  Solution& solution = result.solution;
  SolveReport& report = result.report;
  const ThreadLimit threads = limitSolveThreads(options, report);
  const int n = solution.mesh->elementCount();
  if (n != static_cast<int>(kept.area.size()))
    throw InputError(keptPath, 0,
                     "the scene meshes into " + std::to_string(n) +
                         " elements, the kept factors hold " + std::to_string(kept.area.size()) +
                         ": solve again");
  solution.problem.area = kept.area;
  addKeptFirstShot(kept, lightScale, solution.problem);
  if (!(solution.problem.emittedPower() > 0))
    throw InputError(keptPath, 0, "nothing emits after the overrides: no light to solve for");

  KeptRows rows(kept);
  const std::unique_ptr<Solver> solver =
      makeSolver(options.solver, solution.problem, rows, [&] { return kept.rows.takeMatrix(); });
  solveToLimits(*solver, iterationLimits(options, n, started.start), keepsPointValues(options),
                keptLightsIrradiance(kept, lightScale), solution, report);
  report.shooters = n;
  report.relitFrom = keptPath;
  report.relitLightScale = lightScale;
  for (size_t l = 0; l < lightScale.size(); ++l)
    solution.scene.lights[l] = scaledLight(solution.scene.lights[l], lightScale[l]);
  report.skip("form factors and the lights' first shot",
              "relight: reused from " + keptPath + ", no ray cast");
  report.times.total = secondsSince(started.start);
  report.times.solve = report.times.total;
  return result;
}

SolveResult relightScene(KeptFactors kept, const std::string& keptPath, Scene scene,
                         const std::vector<Rgb>& lightScale, const SolveOptions& solverOptions) {
  RelightStart started = startRelight(kept, keptPath, std::move(scene), solverOptions);
  return finishRelight(std::move(started), std::move(kept), keptPath, lightScale);
}

}  // namespace rad
