#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/scene/scene.h"

namespace rad {

// The scene a kept solve was made from, as its files read now (materials included), with the
// two-sided surfaces and the lights (the scene's own, then its light input's) the solve had.
Scene loadKeptScene(const KeptFactors& kept);

// Solves the kept scene again from its kept factors, casting no ray: the same mesh (uniform
// meshing is deterministic), ρ and E from `scene`'s materials (the caller's overrides applied),
// each light's kept E_d times lightScale[l], and the kept rows and exposed areas. `solverOptions`
// supplies the solver, tolerance, iteration budget and threads. Throws InputError naming
// `keptPath` when the scene's geometry no longer matches the kept factors, or its lights are not
// the ones solved (their E_d is kept, not cast again). The solution's scene has each light scaled
// by lightScale[l] (scaledLight), and the report the scales (relitLightScale): what `bake
// --solution` re-applies to the scene to recognise the relit solution. Takes `kept` by value:
// the gathering solvers take its rows over (move it in when it is not needed again).
SolveResult relightScene(KeptFactors kept, const std::string& keptPath, Scene scene,
                         const std::vector<Rgb>& lightScale, const SolveOptions& solverOptions);

// relightScene in two steps, so that the first can run while the rows are still being read: what
// needs only the kept header (readKeptFactors with KeptParts::Header): the checks, the mesh, ρ and
// E from the materials; then, with the whole kept file, the first shot and the solve.
struct RelightStart {
  SolveResult result;
  SolveOptions options;
  std::chrono::steady_clock::time_point start;
};
RelightStart startRelight(const KeptFactors& header, const std::string& keptPath, Scene scene,
                          const SolveOptions& solverOptions);
SolveResult finishRelight(RelightStart started, KeptFactors kept, const std::string& keptPath,
                          const std::vector<Rgb>& lightScale);

}  // namespace rad
