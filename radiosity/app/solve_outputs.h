#pragma once

#include <vector>

#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/render/light_probes.h"

namespace rad {

// Writes elements.csv, vertex_colors.ply, summary.json (and solution.vtp with the viewer, and
// solution.json for later commands to reuse) into options.outputDir. Every file is written under
// a temporary name and renamed only once all of them are complete.
void writeSolveOutputs(const SolveOptions& options, SolveResult& result);
// The same, with the light probes of `solve --probes` in probes.json and probes.bin, committed
// together with the other files.
void writeSolveOutputs(const SolveOptions& options, SolveResult& result,
                       const std::vector<ProbeSh>& probes);

}  // namespace rad
