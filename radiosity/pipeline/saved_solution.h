#pragma once

#include <optional>
#include <string>

#include "radiosity/core/atomic_file.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"

namespace rad {

// A radiosity solution kept in an output directory for later commands: solution.json says what it
// was solved from (a fingerprint of the scene and the solve options) and names the CSV holding B
// per element in the elements.csv format: elements.csv itself for `solve`, solution.csv for
// `render --method radiosity`. render, bake and view reuse it when the scene and the solve
// options match, so that renders from other cameras or with other sample counts skip the solve.
//
// Reuse re-meshes the scene (uniform meshing is deterministic) and reads B back (and E_d, where
// the CSV has the Ed columns); it needs the fingerprint of the scene's content and of every solve
// option that shapes the mesh or B to match.
// A solution from adaptive refinement is not kept: its mesh depends on the solve.

// Hash of the loaded scene (positions, polygons, materials) and the solve options that decide
// the mesh and B; threads, output directory and time limit excepted.
std::string solutionFingerprint(const Scene& scene, const SolveOptions& options);

// Whether `options` give a mesh that re-meshing reproduces (no adaptive refinement).
bool solutionIsReusable(const SolveOptions& options);

// Loads the solution saved in `dir` for `scene` and `options`. Returns nothing (and sets
// `whyNot`) when there is none or it was made from another scene or other options. Throws
// InputError naming the file and line when the saved files match the fingerprint but are
// malformed or describe another mesh (edited or truncated by hand).
std::optional<SolveResult> loadSavedSolution(const std::string& dir, const Scene& scene,
                                             const SolveOptions& options, std::string& whyNot);

// The elements CSV of `solution` (elements.csv, solution.csv): with its direct irradiance E_d
// (the Ed columns) where it has one, which a reuse reads back into Solution::directIrradiance
// (RAD_CHECK: one per element), and with the buried cells of its exposure where it kept one,
// which a reuse then reads instead of casting probe rays again.
void writeSolutionElementsCsv(std::ostream& out, const Solution& solution);

// Writes solution.csv and solution.json into the temporary files `csv` and `json` (the caller
// commits them with its other outputs).
void writeSavedSolution(AtomicFile& csv, AtomicFile& json, const SolveResult& result,
                        const SolveOptions& options);
// Writes only solution.json, naming `elementsFile` (already written beside it) as its CSV.
void writeSavedSolutionJson(AtomicFile& json, const std::string& elementsFile,
                            const SolveResult& result, const SolveOptions& options);

inline constexpr const char* kSolutionCsv = "solution.csv";
inline constexpr const char* kSolutionJson = "solution.json";

}  // namespace rad
