#pragma once

#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"

namespace rad {

// Writes elements.csv, vertex_colors.ply, summary.json (and solution.vtp with the viewer, and
// solution.json for later commands to reuse) into options.outputDir. Every file is written under
// a temporary name and renamed only once all of them are complete.
void writeSolveOutputs(const SolveOptions& options, SolveResult& result);

}  // namespace rad
