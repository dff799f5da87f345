// `radiosity update DIR`: a solve kept with `solve --keep-factors` brought up to date after its
// scene's geometry was edited (an object moved, added or removed): only the form-factor rows the
// edit can change are cast again, and the solve goes on from the previous solution. The outputs
// (elements.csv, vertex_colors.ply, summary.json, factors.bin, …) are rewritten in DIR, or
// written to --out.
#include <chrono>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <vector>

#include "radiosity/app/commands.h"
#include "radiosity/app/options/option_rules.h"
#include "radiosity/app/solve_outputs.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/interrupt.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/pipeline/incremental_update.h"
#include "radiosity/pipeline/kept_factors.h"

namespace rad {
namespace {

struct UpdateOptions {
  std::string dir;
  std::string outputDir;   // default: dir
  std::string solverName;  // empty: the kept solve's
  std::optional<double> tolerance;
  std::optional<int> maxIterations;
  int threads = 0;
};

void runUpdate(const UpdateOptions& o) {
  const std::filesystem::path dir(o.dir);
  const std::string keptPath = (dir / kKeptFactorsFile).string();
  if (!std::filesystem::exists(keptPath))
    throw InputError(o.dir, 0,
                     "no kept form factors (" + std::string(kKeptFactorsFile) +
                         ") here: solve with --keep-factors --out " + o.dir + " first");
  const std::string csvPath = (dir / "elements.csv").string();
  if (!std::filesystem::exists(csvPath))
    throw InputError(o.dir, 0, "no elements.csv here: the previous solution update starts from");
  auto t = std::chrono::steady_clock::now();
  // The rows, the previous solution and the scene (with its mesh) are read side by side: the
  // file reads are most of a large update's fixed cost.
  const KeptFactors header = readKeptFactors(keptPath, KeptParts::Header);
  std::future<KeptFactors> reading =
      std::async(std::launch::async, [&keptPath] { return readKeptFactors(keptPath); });
  std::future<ElementsCsv> readingPrevious =
      std::async(std::launch::async, [&csvPath] { return readElementsCsv(csvPath); });
  SolveOptions solver = header.options;
  // By default the kept solve's solver, whose answer a fresh solve of the edited scene gives.
  solver.solver = !o.solverName.empty()                           ? parseSolverKind(o.solverName)
                  : continuesFromASolution(header.options.solver) ? header.options.solver
                                                                  : SolverKind::GaussSeidel;
  if (o.tolerance) solver.tolerance = *o.tolerance;
  if (o.maxIterations) solver.maxIterations = *o.maxIterations;
  solver.threads = o.threads;
  solver.outputDir = o.outputDir.empty() ? o.dir : o.outputDir;
  UpdateStart started = startUpdate(header, keptPath, solver);
  const KeptFactors kept = reading.get();
  const ElementsCsv previousCsv = readingPrevious.get();
  PreviousSolution previous;
  for (const ElementsCsvRow& row : previousCsv.rows) {
    previous.radiosity.push_back(row.radiosity);
    if (previousCsv.hasDirectIrradiance) previous.directIrradiance.push_back(row.directIrradiance);
    if (previousCsv.hasBuriedCells) previous.buriedCells.push_back(row.buriedCells);
  }
  if (previous.radiosity.size() != kept.area.size())
    throw InputError(csvPath, 0,
                     std::to_string(previous.radiosity.size()) +
                         " elements, the kept factors beside it " +
                         std::to_string(kept.area.size()) + ": not the same solve");
  logInfo("read " + keptPath + " (" + std::to_string(kept.rows.size()) + " rows), " + csvPath +
          " and the scene, meshed, in " + formatNumber(secondsSince(t)) + " s");
  SolveResult result = finishUpdate(std::move(started), kept, keptPath, previous);
  throwIfInterrupted();
  SolveOptions written = updatedSolutionOptions(kept, result);
  written.outputDir = solver.outputDir;
  written.keepFactors = true;  // factors.bin (with the fixed element size) for the next update
  {
    OutputSection writing;
    writeSolveOutputs(written, result);
  }
  clearInterrupt();
  const SolveReport::Update& u = result.report.update;
  logInfo("updated " + kept.scenePath + " from " + keptPath + " in " +
          formatNumber(result.report.times.total) + " s: " + std::to_string(u.rowsReused) + " of " +
          std::to_string(result.solution.mesh->elementCount()) + " rows reused");
}

}  // namespace

void registerUpdateCommand(CLI::App& app, CommandAction& run) {
  auto o = std::make_shared<UpdateOptions>();
  CLI::App* update = app.add_subcommand(
      "update",
      "Bring a kept solve (solve --keep-factors) up to date after its scene's geometry was edited, "
      "casting again only the rows the edit changes");
  update->add_option("dir", o->dir, "Output directory of `radiosity solve --keep-factors`")
      ->required();
  update->add_option("--out", o->outputDir, "Write the outputs here instead of into DIR");
  update
      ->add_option("--solver", o->solverName,
                   "progressive | gauss-seidel | jacobi, which start from the previous solution "
                   "(default: the kept solve's, or gauss-seidel)")
      ->check(CLI::IsMember({solverKindName(SolverKind::Progressive),
                             solverKindName(SolverKind::GaussSeidel),
                             solverKindName(SolverKind::Jacobi)}));
  update->add_option("--tolerance", o->tolerance, "Relative tolerance (default: the kept solve's)");
  update->add_option("--max-iterations", o->maxIterations, "Iteration budget (0: the default)");
  addThreadsOption(*update, o->threads);
  addCommonFlags(*update);
  update->callback([&run, o] { run = [o] { runUpdate(*o); }; });
}

}  // namespace rad
