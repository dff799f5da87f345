#include "radiosity/app/options/solve_option_group.h"

#include <functional>
#include <vector>

#include "radiosity/app/options/option_rules.h"
#include "radiosity/core/errors.h"
#include "radiosity/scene/lights.h"

namespace rad {
namespace {

// The --help headings, and what a command that does not solve keeps: the scene input and the
// run's seed and threads stay in use by every method; the solve's own options do not.
constexpr const char* kSceneInputGroup = "Scene input";
constexpr const char* kRunGroup = "Seed and threads";
constexpr const char* kSolveGroup = "Solve";

// Puts every option `add` binds into `group`.
void inGroup(CLI::App& command, const char* group, const std::function<void()>& add) {
  const size_t before = command.get_options().size();
  add();
  const std::vector<CLI::Option*> options = command.get_options();
  for (size_t i = before; i < options.size(); ++i) options[i]->group(group);
}

void addSceneInput(CLI::App& command, SolveOptions& options) {
  // The lights besides emissive polygons (read by loadScene with the scene).
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
  command.add_flag_callback(
      "--strict", [&options] { options.unreadableTextures = UnreadableTextures::Refuse; },
      "A texture file that cannot be read is an error (default: a warning naming its MTL line or "
      "glTF image, the material's own colour used instead, and the file listed in the "
      "outputs' JSON as texture_fallbacks)");
}

void addSolve(CLI::App& command, SolveOptions& options) {
  addChoiceOption(command, "--solver", options.solver, solverKindTable(),
                  "progressive: lazy rows; southwell: progressive on all rows; hierarchical: "
                  "links between a tree's nodes (docs/hierarchical.md)");
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
      ->check(positiveNumber());
  command.add_option("--max-area", options.maxArea,
                     "Largest element area in scene units² (instead of --element-size)");
  command
      .add_option("--elements", options.targetElements,
                  "Element count, met within 20% by splitting the largest elements first "
                  "(instead of --element-size)")
      ->check(positiveNumber());
  command
      .add_option("--tolerance", options.tolerance,
                  "Stop at this relative residual (gauss-seidel, jacobi) or unshot fraction "
                  "(progressive, southwell)")
      ->default_val(options.tolerance);
  command.add_option("--max-iterations", options.maxIterations,
                     "Iteration budget: sweeps, bounces or shots (0: solver default)");
  command.add_option("--bounces", options.bounces, "Jacobi only: exactly N bounces of light");
  addChoiceOption(command, "--form-factors", options.formFactors, formFactorMethodTable(),
                  "hemisphere: ray-cast rows per element; analytic: point-to-polygon + shadow "
                  "rays, patches shoot to elements");
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
      ->check(nonNegativeNumber());
  command
      .add_option("--receiver-points", options.receiverPoints,
                  "analytic: sample points per element, 1 or 3")
      ->default_val(options.receiverPoints);
}

// Every option in `group` the user gave is an error saying why.
void refuseGroup(const CLI::App& command, const char* group, const std::string& why) {
  for (const CLI::Option* option : command.get_options())
    if (option->get_group() == group) refuseIfGiven(command, option->get_name(), why);
}

}  // namespace

void addSolveOptions(CLI::App& command, SolveOptions& options) {
  inGroup(command, kSceneInputGroup, [&] { addSceneInput(command, options); });
  inGroup(command, kSolveGroup, [&] { addSolve(command, options); });
  inGroup(command, kRunGroup, [&] {
    command.add_option("--seed", options.seed, "Random seed")->default_val(options.seed);
    addThreadsOption(command, options.threads);
  });
}

void finishSolveOptions(const CLI::App& command, const SolveOptions& options) {
  validateSolveOptions(options);
  checkOptionsApply(options, givenOptions(command));
}

void finishWithoutSolve(const CLI::App& command, const SolveOptions& options,
                        const std::string& whyNoSolve) {
  validateSolveOptions(options);
  refuseGroup(command, kSolveGroup, whyNoSolve);
}

void refuseAllSolveOptions(const CLI::App& command, const std::string& why) {
  for (const char* group : {kSceneInputGroup, kSolveGroup, kRunGroup})
    refuseGroup(command, group, why);
}

}  // namespace rad
