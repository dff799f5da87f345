#pragma once

#include <string>

#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// Where a command's radiosity solution comes from: a solution saved by an earlier `solve` or
// `render` (see saved_solution.h) when it was made from the same scene and solve options, or a
// fresh solve. Which one, and why, is said in the log and in the report.
struct SolutionSource {
  // --solution DIR: the solution must come from here; InputError when DIR holds none for this
  // scene and these options (saying why), rather than a silent solve.
  std::string solutionDir;
  // A directory whose matching solution is reused when there is one (render's --out); otherwise
  // the scene is solved. Empty: none.
  std::string reuseDir;
  // The saved solution must keep each element's E_d (Solution::directIrradiance): the direct/
  // indirect split (--gather 0 --light-rays N) takes its indirect part with it. One without (its
  // elements.csv written before the Ed columns, or by a relight of a scene with mirrors or glass)
  // is then not reused.
  bool needsDirectIrradiance = false;
};

SolveResult solveOrReuse(Scene scene, const SolveOptions& options, const SolutionSource& source);

}  // namespace rad
