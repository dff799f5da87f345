#pragma once

#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"

namespace rad {

// `radiosity update DIR`: a kept solve (solve --keep-factors) brought up to date after its scene's
// geometry was edited (an object moved, added or removed), recomputing only the form-factor rows
// the edit can change.
//
// The scene is loaded as its files read now, with the kept solve's lights and two-sidedness, and
// meshed with the kept element size. An element whose material and corners are exactly as before
// stayed put; the others (and the old elements no longer there) make up the edit's region. An
// element that stayed put keeps its row when none of its row's rays (the same rays a fresh solve
// would cast: the same random streams) meets a triangle of the region, when its exposed area and
// its row's ray budget are unchanged; every other row is cast again. The lights' first shot and
// the buried parts are computed again in full (they cost a fraction of the rows). The solve is a
// gathering solver's (Gauss–Seidel by default; Jacobi), starting from the previous solution
// (`previous`, B per kept element; new elements start from their emission). Returns the solution
// with its kept factors, to be written back for the next update or relight; what the edit changed
// and what was reused are in the report (SolveReport::update).
//
// InputError naming `keptPath`: a scene with mirrors or glass (their rows continue past the first
// hit), a progressive or Southwell solver, `previous` not one value per kept element.
SolveResult updateKeptSolve(const KeptFactors& kept, const std::string& keptPath,
                            const std::vector<Rgb>& previous, const SolveOptions& solverOptions);

// The options the updated solution is saved under (solution.json, so `bake --solution DIR` reuses
// it): the kept solve's own, with the update's solver and tolerance, when its element-size rule
// still picks the kept size for the edited scene (a moved object); else the fixed size the update
// meshed with (an added object that changed the scene's default).
SolveOptions updatedSolutionOptions(const KeptFactors& kept, const SolveResult& updated);

}  // namespace rad
