#pragma once

#include <chrono>
#include <cstdint>
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
// its row's ray budget are unchanged; every other row is cast again. An element that stayed put
// with the same exposed area keeps its direct light from a light (sun, sky, lamp) where none of
// its shadow rays to it can meet the region's bounds (edit_reach.h); the others' is cast again.
// An element that stayed put keeps its buried cells (`previous.buriedCells`, as the previous
// elements.csv holds them) where none of its probe rays can meet the region's bounds; the others
// are probed again, and all of them without them. The solve (`solverOptions.solver`: the kept
// solve's own by default, so that the update converges to what a fresh solve of the edited scene
// gives; progressive, Gauss–Seidel or Jacobi) starts from the previous solution
// (`previous.radiosity`; new elements start from their emission). Returns the solution
// with its kept factors, to be written back for the next update or relight; what the edit changed
// and what was reused are in the report (SolveReport::update).
//
// InputError naming `keptPath`: a scene with mirrors or glass (their rows continue past the first
// hit), a solver that cannot start from a solution (Southwell, hierarchical), `previous` not one
// value per kept element.
//
// An update that finds nothing changed (no element moved, added or removed, every row and every
// light's E_d kept, the materials as solved) returns the previous solution as it is, B and E_d,
// without solving: the kept solve's answer, whichever solver made it.
struct PreviousSolution {
  std::vector<Rgb> radiosity;  // B per kept element (elements.csv)
  std::vector<Rgb>
      directIrradiance;  // E_d per kept element; empty in a file without the Ed columns
  std::vector<uint64_t> buriedCells;  // per kept element; empty in a file without them
};
// The solvers that can start from a previous solution: progressive shooting (its unshot power
// what the solution owes), Gauss–Seidel and Jacobi.
bool continuesFromASolution(SolverKind kind);
SolveResult updateKeptSolve(const KeptFactors& kept, const std::string& keptPath,
                            const PreviousSolution& previous, const SolveOptions& solverOptions);

// updateKeptSolve in two steps, so that the first runs while factors.bin is still being read:
// from the kept header alone (readKeptFactors with KeptParts::Header), the scene loaded, checked
// and meshed with the kept element size; then, with the whole kept file and the previous
// solution, the rest.
struct UpdateStart {
  SolveResult result;  // the scene and its mesh so far
  SolveOptions options;
  std::chrono::steady_clock::time_point start;
};
UpdateStart startUpdate(const KeptFactors& header, const std::string& keptPath,
                        const SolveOptions& solverOptions);
SolveResult finishUpdate(UpdateStart started, const KeptFactors& kept, const std::string& keptPath,
                         const PreviousSolution& previous);

// The options the updated solution is saved under (solution.json, so `bake --solution DIR` reuses
// it): the kept solve's own, with the update's solver and tolerance, when its element-size rule
// still picks the kept size for the edited scene (a moved object); else the fixed size the update
// meshed with (an added object that changed the scene's default).
SolveOptions updatedSolutionOptions(const KeptFactors& kept, const SolveResult& updated);

}  // namespace rad
