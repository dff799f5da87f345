#pragma once

#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The scene a kept solve was made from, as its file reads now (materials included), with the
// two-sided surfaces the solve had; no lights (their first shot is kept).
Scene loadKeptScene(const KeptFactors& kept);

// Solves the kept scene again from its kept factors, casting no ray: the same mesh (uniform
// meshing is deterministic), ρ and E from `scene`'s materials (the caller's overrides applied),
// each light's kept E_d times lightScale[l], and the kept rows and exposed areas. `solverOptions`
// supplies the solver, tolerance, iteration budget and threads. Throws InputError naming
// `keptPath` when the scene's geometry no longer matches the kept factors. Takes `kept` by value:
// the gathering solvers take its rows over (move it in when it is not needed again).
SolveResult relightScene(KeptFactors kept, const std::string& keptPath, Scene scene,
                         const std::vector<Rgb>& lightScale, const SolveOptions& solverOptions);

}  // namespace rad
