#include "radiosity/pipeline/solution_source.h"

#include <chrono>
#include <optional>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/saved_solution.h"
#include "radiosity/pipeline/solve_pipeline.h"

namespace rad {

SolveResult solveOrReuse(Scene scene, const SolveOptions& options, const SolutionSource& source) {
  const auto start = std::chrono::steady_clock::now();
  std::string whyNot;
  std::optional<SolveResult> saved;
  const std::string& dir = source.solutionDir.empty() ? source.reuseDir : source.solutionDir;
  if (!dir.empty()) saved = loadSavedSolution(dir, scene, options, whyNot);
  if (saved && source.needsDirectIrradiance && saved->solution.directIrradiance.empty()) {
    whyNot =
        "its elements.csv has no E_d (the Ed_r,Ed_g,Ed_b columns), which --gather 0 "
        "--light-rays takes the indirect light with: written before they were kept, or by a "
        "relight of a scene with mirrors or glass";
    saved.reset();
  }
  if (!saved && !source.solutionDir.empty())
    throw InputError(source.solutionDir, 0, "no solution to reuse: " + whyNot);
  if (!saved) {
    if (!dir.empty()) logInfo("solving (" + whyNot + ")");
    return solveScene(std::move(scene), options);
  }
  saved->report.skip("radiosity solve",
                     "reused the solution saved in " + dir + " (same scene and solve options)");
  saved->report.times.total = secondsSince(start);
  return std::move(*saved);
}

}  // namespace rad
