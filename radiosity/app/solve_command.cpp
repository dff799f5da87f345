// `radiosity solve SCENE.obj --out DIR`: the diffuse radiosity solution and its files.
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radiosity/app/commands.h"
#include "radiosity/app/solve_outputs.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/render/light_probes.h"
#include "radiosity/render/render_scene.h"
#include "radiosity/scene/lights.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

void addCommonFlags(CLI::App& command) {
  command.add_flag_callback(
      "--quiet,-q", [] { setLogLevel(LogLevel::Quiet); }, "Only warnings and errors on stderr");
}

// Options shared by every command that solves first (solve, render, bake, view).
void addSolveOptions(CLI::App& command, SolveOptions& options, std::string& solverName) {
  // Scene input: the lights besides emissive polygons (read by loadScene with the scene).
  command.add_option(
      "--lights", options.lights.file,
      "Lights file (JSON: point, spot, directional, sky, environment; see docs/physics.md); "
      "default: <scene>.lights.json beside the scene when it exists");
  command
      .add_option_function<std::vector<double>>(
          "--sky",
          [&options](const std::vector<double>& v) {
            options.lights.shortcuts.push_back(skyLight({v[0], v[1], v[2]}));
          },
          "Uniform sky of radiance R G B (W/(m^2 sr)) over the hemisphere above +y")
      ->expected(3)
      ->type_name("R G B");
  command
      .add_option_function<std::vector<double>>(
          "--sun",
          [&options](const std::vector<double>& v) {
            options.lights.shortcuts.push_back(sunLight({v[0], v[1], v[2]}, {v[3], v[4], v[5]}));
          },
          "Sun travelling along DX DY DZ with irradiance R G B (W/m^2 on a surface facing "
          "it), angular diameter 0.53 degrees")
      ->expected(6)
      ->type_name("DX DY DZ R G B");
  command.add_flag("--two-sided", options.twoSided.all,
                   "Every surface is two-sided: lit, reflecting and seen on both sides, each side "
                   "with its own radiosity (glTF says it per material: doubleSided)");
  command
      .add_option("--two-sided-materials", options.twoSided.materials,
                  "These materials (comma-separated names) are two-sided")
      ->delimiter(',')
      ->type_name("NAME,...");
  command
      .add_option(
          "--solver", solverName,
          "progressive (lazy rows) | southwell (progressive on all rows) | gauss-seidel | jacobi "
          "| hierarchical (links between a tree's nodes, docs/hierarchical.md)")
      ->default_val("progressive")
      ->check(
          CLI::IsMember({"progressive", "southwell", "gauss-seidel", "jacobi", "hierarchical"}));
  command
      .add_option("--link-epsilon", options.linkEpsilon,
                  "hierarchical: the most light one link may carry, as a fraction of the emitted "
                  "power per element; smaller: more links, closer to the full-matrix solution")
      ->default_val(options.linkEpsilon);
  command.add_option("--rays", options.raysPerElement, "Hemisphere rays per element")
      ->default_val(options.raysPerElement);
  command
      .add_option("--element-size", options.elementSize,
                  "Element size S in scene units: no element larger than the equilateral "
                  "triangle of edge S (default: from the scene's extent and area, see "
                  "docs/options.md)")
      ->check(CLI::PositiveNumber);
  command.add_option("--max-area", options.maxArea,
                     "Largest element area in scene units² (instead of --element-size)");
  command
      .add_option("--elements", options.targetElements,
                  "Element count, met within 20% by splitting the largest elements first "
                  "(instead of --element-size)")
      ->check(CLI::PositiveNumber);
  command.add_option("--seed", options.seed, "Random seed")->default_val(options.seed);
  command.add_option("--threads", options.threads, "Worker threads (0: all cores)")
      ->default_val(options.threads);
  command
      .add_option("--tolerance", options.tolerance,
                  "Stop at this relative residual (gauss-seidel, jacobi) or unshot fraction "
                  "(progressive, southwell)")
      ->default_val(options.tolerance);
  command.add_option("--max-iterations", options.maxIterations,
                     "Iteration budget: sweeps, bounces or shots (0: solver default)");
  command.add_option("--bounces", options.bounces, "Jacobi only: exactly N bounces of light");
  command
      .add_option_function<std::string>(
          "--form-factors",
          [&options](const std::string& name) {
            options.formFactors = parseFormFactorMethod(name);
          },
          "hemisphere (ray-cast rows per element) | analytic (point-to-polygon + shadow rays, "
          "patches shoot to elements)")
      ->check(CLI::IsMember({"hemisphere", "analytic"}));
  command.add_option("--patch-area", options.patchArea,
                     "analytic: largest shooting patch area (default 8 × the element area)");
  command
      .add_option("--shadow-rays", options.shadowRays,
                  "analytic: visibility rays per receiver point and patch")
      ->default_val(options.shadowRays);
  command.add_option("--refine-threshold", options.refineThreshold,
                     "adaptive refinement (analytic, progressive): elements whose displayed "
                     "(vertex-interpolated) radiance departs from their solved value by more than "
                     "this fraction, or that a shadow boundary crosses, may be split, largest "
                     "area × error² first (0: uniform mesh only)");
  command.add_option("--min-area", options.minArea,
                     "refinement: smallest element area (default: total area / max elements / 16)");
  command.add_option(
      "--max-elements", options.maxElements,
      "refinement: element budget, spent over the passes (default: 8 × the uniform mesh)");
  command
      .add_option("--refine-passes", options.refinePasses,
                  "refinement: solve-and-refine rounds; each grows the mesh by the same factor "
                  "towards --max-elements")
      ->default_val(options.refinePasses);
  command
      .add_option("--time-limit", options.timeLimit,
                  "Stop iterating after this many seconds and keep the solution so far, flagged "
                  "as not converged in summary.json (0: no limit)")
      ->check(CLI::NonNegativeNumber);
  command
      .add_option("--receiver-points", options.receiverPoints,
                  "analytic: sample points per element, 1 or 3")
      ->default_val(options.receiverPoints);
}

namespace {
// The options of addSolveOptions that only the radiosity solve reads.
const char* const kSolveOnlyOptions[] = {
    "--solver",          "--rays",         "--max-area",       "--elements",
    "--element-size",    "--tolerance",    "--max-iterations", "--bounces",
    "--form-factors",    "--patch-area",   "--shadow-rays",    "--refine-threshold",
    "--min-area",        "--max-elements", "--refine-passes",  "--time-limit",
    "--receiver-points", "--link-epsilon"};
}  // namespace

std::set<std::string> givenOptions(const CLI::App& command) {
  std::set<std::string> given;
  for (const CLI::Option* option : command.get_options())
    if (option->count() > 0) given.insert(option->get_name());
  return given;
}

void finishSolveOptions(const CLI::App& command, SolveOptions& options,
                        const std::string& solverName, const std::string& whyNoSolve) {
  options.solver = parseSolverKind(solverName);
  validateSolveOptions(options);
  const std::set<std::string> given = givenOptions(command);
  if (!whyNoSolve.empty()) {
    // Only the options every method reads (--seed, --threads) remain.
    for (const char* name : kSolveOnlyOptions)
      if (given.count(name)) throw InputError(std::string(name) + " is not used: " + whyNoSolve);
    return;
  }
  checkOptionsApply(options, given);
}

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
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  logInfo("light probes: " + std::to_string(probes.size()) + " (" + std::to_string(inside) +
          " inside geometry), " + std::to_string(o.rays) + " rays each, " + formatNumber(seconds) +
          " s");
  return probes;
}

}  // namespace

void registerSolveCommand(CLI::App& app, CommandAction& run) {
  auto options = std::make_shared<SolveOptions>();
  auto solverName = std::make_shared<std::string>("progressive");
  CLI::App* solve = app.add_subcommand("solve", "Solve the diffuse radiosity of a scene");
  solve->add_option("scene", options->scenePath, "OBJ scene file (materials from its MTL)")
      ->required();
  solve->add_option("--out", options->outputDir, "Output directory (created if missing)")
      ->required();
  addSolveOptions(*solve, *options, *solverName);
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
  solve->callback([&run, solve, options, solverName, probes] {
    run = [solve, options, solverName, probes] {
      validateProbeOptions(*probes);
      if (!probes->spacing && solve->count("--probe-rays") > 0)
        throw InputError("--probe-rays is not used: light probes are off without --probes SPACING");
      finishSolveOptions(*solve, *options, *solverName);
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
