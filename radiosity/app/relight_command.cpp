// `radiosity relight DIR [--override FILE]`: a solve kept with `solve --keep-factors` solved
// again with other material colours, emission or light strengths, from its kept form factors and
// first shot: no ray is cast. The outputs (elements.csv, vertex_colors.ply, summary.json, …) are
// rewritten in DIR, or written to --out.
#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <memory>
#include <optional>

#include "radiosity/app/commands.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/solve_outputs.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/relight.h"
#include "radiosity/scene/scene_overrides.h"

namespace rad {
namespace {

struct RelightOptions {
  std::string dir;
  std::string overrideFile;
  std::string outputDir;  // default: dir
  std::optional<std::string> solverName;
  std::optional<double> tolerance;
  std::optional<int> maxIterations;
  int threads = 0;
};

void runRelight(const RelightOptions& o) {
  const std::string keptPath = (std::filesystem::path(o.dir) / kKeptFactorsFile).string();
  if (!std::filesystem::exists(keptPath))
    throw InputError(o.dir, 0,
                     "no kept form factors (" + std::string(kKeptFactorsFile) +
                         ") here: solve with --keep-factors --out " + o.dir + " first");
  // The scene loads from the header's path, and is checked and meshed, while the rows are read
  // (most of a large relight's time): the two overlap.
  const auto t = std::chrono::steady_clock::now();
  const KeptFactors header = readKeptFactors(keptPath, KeptParts::Header);
  std::future<KeptFactors> reading =
      std::async(std::launch::async, [&keptPath] { return readKeptFactors(keptPath); });
  Scene scene = loadKeptScene(header);
  std::vector<Rgb> lightScale(header.lightTypes.size(), Rgb::all(1));
  std::map<int, MaterialOverride> materialChanges;
  if (!o.overrideFile.empty()) {
    std::vector<std::string> materialNames;
    for (const Material& m : scene.materials) materialNames.push_back(m.name);
    const SceneOverrides overrides =
        loadSceneOverrides(o.overrideFile, materialNames, header.lightGroups);
    for (const auto& [index, change] : overrides.materials)
      applyMaterialOverride(scene.materials[static_cast<size_t>(index)], change);
    lightScale = overrides.lightScale;
    materialChanges = overrides.materials;
  }
  SolveOptions solver = header.options;
  if (o.solverName) solver.solver = parseSolverKind(*o.solverName);
  if (o.tolerance) solver.tolerance = *o.tolerance;
  if (o.maxIterations) solver.maxIterations = *o.maxIterations;
  solver.threads = o.threads;
  solver.outputDir = o.outputDir.empty() ? o.dir : o.outputDir;
  // The checks and the mesh while the rows are still being read.
  RelightStart started = startRelight(header, keptPath, std::move(scene), solver);
  KeptFactors kept = reading.get();
  logInfo("read " + keptPath + " (" + std::to_string(kept.rows.size()) + " rows, " +
          std::to_string(kept.rows.factorCount()) + " factors), the scene and its mesh in " +
          formatNumber(secondsSince(t)) + " s");
  SolveResult result = finishRelight(std::move(started), std::move(kept), keptPath, lightScale);
  result.report.relitMaterials = std::move(materialChanges);  // for solution.json
  throwIfInterrupted();
  SolveOptions written = header.options;
  written.solver = solver.solver;
  written.tolerance = solver.tolerance;
  written.maxIterations = solver.maxIterations;
  written.outputDir = solver.outputDir;
  written.keepFactors = false;  // factors.bin stays as the solve wrote it
  {
    OutputSection writing;
    writeSolveOutputs(written, result);
  }
  clearInterrupt();
  logInfo("relit " + header.scenePath + " from " + keptPath + " in " +
          formatNumber(result.report.times.total) + " s, no ray cast");
}

}  // namespace

void registerRelightCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<RelightOptions>();
  CLI::App* relight = app.add_subcommand(
      "relight",
      "Solve a kept solve (solve --keep-factors) again with other colours or light strengths, "
      "casting no ray");
  relight->add_option("dir", o->dir, "Output directory of `radiosity solve --keep-factors`")
      ->required();
  relight
      ->add_option("--override", o->overrideFile,
                   "JSON file: {\"materials\": {NAME: {\"diffuse\": [r,g,b], \"emission\": "
                   "[r,g,b]}}, \"lights\": {INDEX or GROUP: {\"scale\": k or [r,g,b]}}}")
      ->check(CLI::ExistingFile);
  relight->add_option("--out", o->outputDir, "Write the outputs here instead of into DIR");
  relight->add_option("--solver", o->solverName,
                      "Solver (default: the kept solve's, so an unchanged scene gives its answer "
                      "back; gauss-seidel is fastest over kept rows): " +
                          solverKindNames());
  relight->add_option("--tolerance", o->tolerance,
                      "Relative tolerance (default: the kept solve's)");
  relight->add_option("--max-iterations", o->maxIterations, "Iteration budget (0: the default)");
  addThreadsOption(*relight, o->threads);
  addCommonFlags(*relight);
  relight->callback([&run, o] { run = [o] { runRelight(*o); }; });
}

}  // namespace rad
