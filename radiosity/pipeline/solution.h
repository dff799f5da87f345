#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/hierarchical/element_links.h"
#include "radiosity/scene/light_groups.h"
#include "radiosity/scene/scene.h"
#include "radiosity/scene/scene_overrides.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// One light group's share of the solution (--light-groups): B per element, and at the receiver
// points where the whole solution keeps them.
struct LightLayer {
  LightGroup group;
  std::vector<Rgb> radiosity;
  std::vector<std::array<Rgb, 3>> pointRadiosity;
};

// What a solve produced that writers, renderers and the viewer read: the scene, its mesh, the
// per-element problem and the radiosity on it.
struct Solution {
  Scene scene;
  std::unique_ptr<PatchMesh> mesh;
  RadiosityProblem problem;
  std::vector<Rgb> radiosity;  // B per element, W/m² (for scenes in metres)
  // B at each element's 3 Gauss points (analytic factors with 3 receiver points and progressive
  // shooting; their mean is `radiosity`), or empty: what vertex colours interpolate from.
  std::vector<std::array<Rgb, 3>> pointRadiosity;
  // E_d per element (W/m²): the irradiance each element received straight from the emitters and
  // the lights, as the solve computed it (the lights' first shot; the emitters' light through the
  // solver's own form factors, or a hierarchical solve's shadow rays to them), so that
  // B − E − ρ E_d is the interreflected light by the same estimator as B. 0 on black elements
  // (ρ = 0: they pass nothing on). Empty when not known (a saved solution written before
  // elements.csv had the Ed columns).
  std::vector<Rgb> directIrradiance;
  // Unshot power per element (W) a shooting solver still held; empty for gathering solvers.
  std::vector<Rgb> unshot;
  // With keepBounceTerms: term k = B_k − B_{k−1} = (rho F)^k E of the Jacobi iterates, k ≥ 0.
  std::vector<std::vector<Rgb>> bounceTerms;
  // With --light-groups: one layer per light group; `radiosity` and `pointRadiosity` are their
  // sums. Empty otherwise.
  std::vector<LightLayer> layers;
  // With keepLinks and --solver hierarchical: the links each element gathers over, for the
  // viewer. Null otherwise.
  std::shared_ptr<const ElementLinks> links;
  // The parts of elements no ray reaches (solveExposure), as the solve found them on `mesh`, for
  // the bake's buried texels; null when the mesh changed since (refinement) or nobody kept it.
  std::shared_ptr<const ElementExposure> exposure;
};

// Why the iterations stopped.
enum class StopReason { Tolerance, Bounces, IterationLimit, TimeLimit };
// "tolerance", "bounces", "iteration limit", "time limit" (summary.json's stopped_by).
std::string stopReasonName(StopReason reason);

// Something the run decided not to do, and why (reported in the log and summary.json).
struct SkipNote {
  std::string what, why;
};

struct StageTimes {
  double load = 0, mesh = 0, bvh = 0, formFactors = 0, solve = 0, output = 0, total = 0;
};

// How the solve went: counts, times, the stopping state and the work skipped.
struct SolveReport {
  std::string solverName, progressMeasure;
  int iterations = 0;
  int refinementPasses = 0;
  int elementsBeforeRefinement = 0;
  double finalProgress = 0;  // residual or unshot fraction reached
  bool converged = false;
  StopReason stoppedBy = StopReason::Tolerance;
  double maxArea = 0;           // the element area bound (with --elements: the largest)
  double elementSize = 0;       // S of radiosity/pipeline/element_size.h
  std::string elementSizeRule;  // which rule set it: elementSizeRuleName
  int shooters = 0;             // elements (hemisphere) or shooting patches (analytic)
  int rowsComputed = 0;
  uint64_t specularRays = 0;  // continuations through mirrors and glass
  uint64_t raysCast = 0;
  uint64_t directLightRays = 0;  // the first shot of the scene's lights: shadow rays cast
  // Buried parts of elements (element_exposure.h): elements partly and fully buried, the buried
  // share of the total area, and the probe rays that found them.
  int partlyBuried = 0, fullyBuried = 0;
  double buriedAreaFraction = 0;
  uint64_t exposureProbeRays = 0;
  int threads = 0;
  bool reusedSavedSolution = false;
  std::string relitFrom;  // relight: the kept factors the solve reused (no ray cast)
  // relight's overrides: the materials changed (by index) and each light's scale.
  std::map<int, MaterialOverride> relitMaterials;
  std::vector<Rgb> relitLightScale;
  // update (incremental_update.h): the kept factors it started from and what the edit changed.
  struct Update {
    std::string keptFactors;      // empty: not an update
    int moved = 0;                // elements not in the kept mesh (moved or added)
    int removed = 0;              // kept elements no longer in the mesh (moved or removed)
    int rowsReused = 0;           // kept rows taken as they were: no ray meets the edit first
    int rowsUpdated = 0;          // kept rows brought up to date ray by ray
    uint64_t raysChanged = 0;     // … the rays among theirs whose first hit changed
    uint64_t raysTested = 0;      // rays of the kept rows made and tested against the edit (the
                                  // others' direction strata cannot point at it)
    uint64_t raysOfKeptRows = 0;  // all the rays of the kept rows examined
    int rowsOtherChange = 0;      // rows of unmoved elements cast again: their exposed area or ray
                                  // budget changed, or old and new hits tied
    int64_t directLightKept = 0;  // (element, light) pairs whose E_d was kept: no shadow ray of
                                  // theirs can meet the edit
    int buriedCellsKept = 0;      // elements whose buried cells were kept: no probe ray of theirs
                                  // can meet the edit
  } update;
  // --solver hierarchical (hierarchical_solve.h): the tree, its links and what they cost.
  struct Hierarchy {
    int nodes = 0;  // 0: not a hierarchical solve
    int clusters = 0, depth = 0;
    int64_t links = 0;
    int receivers = 0;         // nodes that gather over links of their own
    int linkPasses = 0;        // links made, then refined again after each solve (BF refinement)
    int64_t linksRefined = 0;  // links split by those passes
    int64_t treeBytes = 0, linkBytes = 0, solverBytes = 0;
  } hierarchy;
  StageTimes times;
  std::vector<SkipNote> skipped;

  // Logs "skipped: what (why)" and keeps the note for summary.json.
  void skip(std::string what, std::string why);
};

struct KeptFactors;

struct SolveResult {
  Solution solution;
  SolveReport report;
  // With --keep-factors: what relight needs (kept_factors.h); null otherwise.
  std::shared_ptr<const KeptFactors> kept;
};

}  // namespace rad
