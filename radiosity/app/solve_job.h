#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/formfactors/specular_paths.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/radiosity_problem.h"

namespace rad {

enum class SolverKind { Progressive, Southwell, GaussSeidel, Jacobi };
SolverKind parseSolverKind(const std::string& name);  // throws InputError for unknown names
std::string solverKindName(SolverKind kind);

enum class FormFactorMethod { Hemisphere, Analytic };
FormFactorMethod parseFormFactorMethod(const std::string& name);  // throws InputError

struct SolveOptions {
  std::string scenePath;
  std::string outputDir;
  SolverKind solver = SolverKind::Progressive;
  int raysPerElement = 1024;
  double maxArea = 0;         // scene units²; 0: totalArea / targetElements
  int targetElements = 1500;  // used when maxArea is 0
  uint64_t seed = 1;
  int threads = 0;  // 0: all hardware threads
  double tolerance = 1e-4;
  int maxIterations = 0;         // 0: a default per solver
  int bounces = -1;              // Jacobi only: exactly this many bounces (overrides tolerance)
  bool keepBounceTerms = false;  // Jacobi only: keep each iteration's term (rho F)^k E
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
};

// Something the run decided not to do, and why (reported in the log and summary.json).
struct SkipNote {
  std::string what, why;
};

struct StageTimes {
  double load = 0, mesh = 0, bvh = 0, formFactors = 0, solve = 0, output = 0, total = 0;
};

// Everything a solve produced, for the writers and for tests.
struct SolveResult {
  Scene scene;
  std::unique_ptr<PatchMesh> mesh;
  RadiosityProblem problem;
  std::vector<Rgb> radiosity;  // B per element, W/m² (for scenes in metres)
  // B at each element's 3 Gauss points (analytic factors with 3 receiver points and progressive
  // shooting; their mean is `radiosity`), or empty: what vertex colours interpolate from.
  std::vector<std::array<Rgb, 3>> pointRadiosity;
  // With keepBounceTerms: term k = B_k − B_{k−1} = (rho F)^k E of the Jacobi iterates, k ≥ 0.
  std::vector<std::vector<Rgb>> bounceTerms;
  std::string solverName, progressMeasure;
  int iterations = 0;
  int refinementPasses = 0;
  int elementsBeforeRefinement = 0;
  double finalProgress = 0;  // residual or unshot fraction reached
  bool converged = false;
  std::string stoppedBy;  // "tolerance", "bounces", "iteration limit" or "time limit"
  double maxArea = 0;
  std::string formFactorMethod;
  int shooters = 0;  // elements (hemisphere) or shooting patches (analytic)
  int rowsComputed = 0;
  uint64_t specularRays = 0;  // continuations through mirrors and glass
  uint64_t raysCast = 0;
  int threads = 0;
  StageTimes times;
  std::vector<SkipNote> skipped;
};

// Loads options.scenePath, then solveScene(). Throws InputError for bad input.
SolveResult runSolve(const SolveOptions& options);
// Meshes, computes form factors and solves an already loaded scene (options.scenePath unused).
SolveResult solveScene(Scene scene, const SolveOptions& options);

// Rays per emitter row relative to an average row: about the element's share of the emitted
// power times the element count, between 1 and 64.
std::vector<int> emitterRayMultipliers(const RadiosityProblem& problem);
// The iteration budget a solver gets when --max-iterations is not given.
int defaultMaxIterations(SolverKind kind, int elements);

// Mirror and glass behaviour per element for extended form factors.
std::vector<SpecularSurface> specularSurfaces(const Scene& scene, const PatchMesh& mesh);

// The per-element problem of a meshed scene: E = pi·Ke on emitters, rho = Kd (0 on mirrors
// and glass, which hold no radiosity).
RadiosityProblem makeProblem(const Scene& scene, const PatchMesh& mesh);

// Resource limits, decided before the work starts (issue 9).
// Upper bound on the memory of the form-factor rows a run may store: hemisphere rows hold at
// most min(rays, elements) entries each; analytic rows (gathering matrix or patch shots) at
// most elements × shooters entries; about 12 bytes per entry (index and value), 24 for analytic
// rows that also keep the factor at each of 3 receiver points (receiverPoints 3).
uint64_t formFactorMemoryEstimate(FormFactorMethod method, int elements, int shooters, int rays,
                                  int receiverPoints = 1);
// MemAvailable from /proc/meminfo in bytes; 0 when unknown (the check is then skipped).
uint64_t availableMemoryBytes();
// Throws InputError naming the options to change when `needed` exceeds `available` (0: unknown).
void checkFormFactorMemory(uint64_t needed, uint64_t available, FormFactorMethod method);
// Throws InputError (naming the file) for scenes too large or too far out to solve: more
// polygons than the element limit, coordinates beyond kMaxCoordinate. (Faces of more than 255
// vertices are refused by the OBJ line check.)
void checkSceneLimits(const Scene& scene);
inline constexpr double kMaxCoordinate = 1e15;

// Writes elements.csv, vertex_colors.ply and summary.json into options.outputDir. Every file is
// written under a temporary name and renamed only once all of them are complete.
void writeSolveOutputs(const SolveOptions& options, SolveResult& result);

}  // namespace rad
