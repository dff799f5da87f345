#pragma once

#include <cstdint>
#include <set>
#include <string>

#include "radiosity/core/named_values.h"
#include "radiosity/scene/lights.h"
#include "radiosity/scene/scene.h"
#include "radiosity/scene/two_sided.h"
#include "radiosity/solvers/solver_factory.h"

namespace rad {

// How form factors are computed: hemisphere rows per element (ray cast), or analytic
// element-to-patch factors (point-to-polygon with shadow rays; patches shoot, elements receive).
enum class FormFactorMethod { Hemisphere, Analytic };
const NameTable<FormFactorMethod>& formFactorMethodTable();       // "hemisphere", "analytic"
FormFactorMethod parseFormFactorMethod(const std::string& name);  // throws InputError
std::string formFactorMethodName(FormFactorMethod method);

// Everything that decides a solve: the mesh, the form factors, the solver and its stopping rule.
// The same defaults serve every command that solves (solve, render, bake, view, compare).
struct SolveOptions {
  std::string scenePath;
  std::string outputDir;
  LightInput lights;       // scene input: --lights FILE (default the sidecar), --sky, --sun
  TwoSidedInput twoSided;  // scene input: --two-sided, --two-sided-materials
  // scene input: a texture file that cannot be read is a warning and a fallback, or with --strict
  // an error (scene/scene.h).
  UnreadableTextures unreadableTextures = UnreadableTextures::UseMaterialColour;
  SolverKind solver = SolverKind::Progressive;
  int raysPerElement = 1024;  // hemisphere: rays per element row (hierarchical: per receiver)
  double linkEpsilon = 0.01;  // hierarchical: most light a link carries / (emitted power/elements)
  // Element size (radiosity/pipeline/element_size.h): at most one of the three is given; none
  // given, the size derives from the scene's extent and area.
  double maxArea = 0;      // scene units²: largest element area; 0: not given
  double elementSize = 0;  // scene units: edge of the equilateral triangle of the largest
                           // element area; 0: not given
  int targetElements = 0;  // element count, met within about 20%; 0: not given
  uint64_t seed = 1;
  int threads = 0;  // 0: all hardware threads
  double tolerance = 1e-4;
  int maxIterations = 0;         // 0: a default per solver
  int bounces = -1;              // Jacobi only: exactly this many bounces (overrides tolerance)
  bool keepBounceTerms = false;  // Jacobi only: keep each iteration's term (rho F)^k E
  bool keepLinks = false;  // hierarchical only: keep the links in Solution::links (the viewer)
  FormFactorMethod formFactors = FormFactorMethod::Hemisphere;
  double patchArea = 0;        // analytic: largest shooting patch (scene units²); 0: 8 × max area
  int shadowRays = 16;         // analytic: visibility rays per receiver point and patch
  int receiverPoints = 3;      // analytic: 1 (centroid) or 3 (Gauss points) per element
  double refineThreshold = 0;  // adaptive refinement: relative error of the displayed radiance
                               // that makes an element a candidate for splitting; 0: off
  double minArea = 0;    // refinement: smallest element area; 0: total area / max elements / 16
  int maxElements = 0;   // refinement: element budget; 0: 8 × the uniform mesh's count
  int refinePasses = 8;  // refinement: solve–refine rounds
  double timeLimit = 0;  // seconds from the start of the solve; 0: none. Past it the
                         // iterations stop and the solution so far is kept (not converged)
  // bake --light-groups: one solve per light group (scene/light_groups.h) over the same form
  // factors, kept as Solution::layers; the whole solution is their sum.
  bool lightGroups = false;
  // solve --keep-factors: keep the rows, exposed areas and each light's E_d (kept_factors.h) for
  // `relight`; every row is computed, and emitter rows get rays by sourceRayMultipliers.
  bool keepFactors = false;
};

// Throws InputError for values no solve can use (non-positive counts, NaN, out-of-range).
void validateSolveOptions(const SolveOptions& options);

// Throws InputError when an option the user gave (`given`: the long names, e.g. "--rays") does
// nothing with the chosen method or solver, saying why, as pbrt-v4 reports unused parameters.
void checkOptionsApply(const SolveOptions& options, const std::set<std::string>& given);

}  // namespace rad
