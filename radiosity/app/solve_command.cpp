// `radiosity solve SCENE.obj --out DIR`: the diffuse radiosity solution and its files.
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/app/commands.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/options/solve_option_group.h"
#include "radiosity/app/solve_outputs.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/light_probes.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/lights.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

namespace {

// `solve --probes`: light probes on a grid over the solved mesh's bounding box.
struct ProbeOptions {
  std::optional<double> spacing;
  int rays = 1024;
};

void validateProbeOptions(const ProbeOptions& o) {
  if (!o.spacing) return;
  if (!(*o.spacing > 0) || !std::isfinite(*o.spacing))
    throw InputError("--probes must be a positive number of scene units");
  if (o.rays < 1) throw InputError("--probe-rays must be at least 1");
}

std::vector<ProbeSh> solveProbes(const SolveOptions& options, const ProbeOptions& o,
                                 const SolveResult& result) {
  const auto start = std::chrono::steady_clock::now();
  const Solution& solution = result.solution;
  const PatchMesh& mesh = *solution.mesh;
  const RayCaster caster(mesh, solution.scene);
  const RenderScene view(solution.scene, mesh, caster);
  const std::vector<Eigen::Vector3d> points =
      probeGrid(mesh.boundsMin(), mesh.boundsMax(), *o.spacing);
  std::vector<ProbeSh> probes =
      computeProbes(view, solution.radiosity, points, o.rays, options.seed);
  int inside = 0;
  for (const ProbeSh& p : probes) inside += p.inside;
  const double seconds = secondsSince(start);
  logInfo("light probes: " + std::to_string(probes.size()) + " (" + std::to_string(inside) +
          " inside geometry), " + std::to_string(o.rays) + " rays each, " + formatNumber(seconds) +
          " s");
  return probes;
}

}  // namespace

void registerSolveCommand(CLI::App& app, CommandAction& run) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* solve = app.add_subcommand("solve", "Solve the diffuse radiosity of a scene");
  solve
      ->add_option("scene", options->scenePath,
                   std::string(kSceneFileHelp) + "; materials from its MTL or glTF")
      ->required();
  solve->add_option("--out", options->outputDir, "Output directory (created if missing)")
      ->required();
  addSolveOptions(*solve, *options);
  solve->add_flag("--keep-factors", options->keepFactors,
                  "Keep the form factors, exposed areas and each light's first shot in "
                  "factors.bin, so `radiosity relight` can change colours and light strengths "
                  "without casting a ray (hemisphere rows, uniform mesh)");
  auto probes = std::make_shared<ProbeOptions>();
  solve->add_option("--probes", probes->spacing,
                    "Light probes (order-2 SH of the incident radiance) on a grid of this spacing "
                    "in scene units over the mesh's bounding box: probes.json and probes.bin "
                    "(docs/rendering.md)");
  solve->add_option("--probe-rays", probes->rays, "Rays per light probe")
      ->default_val(probes->rays);
  addCommonFlags(*solve);
  solve->callback([&run, solve, options, probes] {
    run = [solve, options, probes] {
      validateProbeOptions(*probes);
      if (!probes->spacing)
        refuseIfGiven(*solve, "--probe-rays", "light probes are off without --probes SPACING");
      finishSolveOptions(*solve, *options);
      SolveResult result = runSolve(*options);
      throwIfInterrupted();
      std::vector<ProbeSh> probeSh;
      if (probes->spacing) {
        probeSh = solveProbes(*options, *probes, result);
        throwIfInterrupted();
      }
      {
        // The files are written and renamed as a set; a signal now waits for it to finish.
        OutputSection writing;
        if (probes->spacing)
          writeSolveOutputs(*options, result, probeSh);
        else
          writeSolveOutputs(*options, result);
      }
      clearInterrupt();  // a signal that came while writing came too late: the run completed
    };
  });
}

}  // namespace rad
