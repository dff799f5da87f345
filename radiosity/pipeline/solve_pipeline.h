#pragma once

#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The solve, stage by stage: load → mesh → form factors → solve ⇄ refine → solution.
// Every command that needs a radiosity solution, the tests and the benchmarks go through here.

// Loads options.scenePath, then solveScene(). Throws InputError for bad input.
SolveResult runSolve(const SolveOptions& options);
// Meshes, computes form factors and solves an already loaded scene (options.scenePath unused).
SolveResult solveScene(Scene scene, const SolveOptions& options);

}  // namespace rad
