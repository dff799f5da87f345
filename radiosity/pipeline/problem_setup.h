#pragma once

#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/formfactors/specular_paths.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The per-element problem of a meshed scene: E = pi·Ke on emitters, rho = Kd (0 on mirrors
// and glass, which hold no radiosity), each times its texture's area average over the element;
// A = the element's area, or with `exposure` its exposed area (element_exposure.h).
RadiosityProblem makeProblem(const Scene& scene, const PatchMesh& mesh,
                             const ElementExposure* exposure = nullptr);

// The buried parts of elements a solve with `options` takes into account: found by probe rays
// with hemisphere rows; none with analytic factors (they sample their receivers at fixed points
// and are refined instead). A saved solution, when reused, gets the same.
ElementExposure solveExposure(const SolveOptions& options, const PatchMesh& mesh,
                              const RayCaster& rays);

// Mirror and glass behaviour per element for extended form factors.
std::vector<SpecularSurface> specularSurfaces(const Scene& scene, const PatchMesh& mesh);

// Rays per emitter row relative to an average row: about the element's share of the emitted
// power times the element count, between 1 and 64.
std::vector<int> emitterRayMultipliers(const RadiosityProblem& problem);
// The same for several sources of power (per element, one vector per source): each element's
// largest share of any one source. Scaling a source leaves every row's rays as they were, which
// light groups and kept factors rely on.
std::vector<int> sourceRayMultipliers(const std::vector<double>& area,
                                      const std::vector<std::vector<Rgb>>& sourcePower);

}  // namespace rad
