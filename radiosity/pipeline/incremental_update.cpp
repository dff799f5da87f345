#include "radiosity/pipeline/incremental_update.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <numeric>
#include <unordered_map>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/pipeline/edit_reach.h"
#include "radiosity/pipeline/element_size.h"
#include "radiosity/pipeline/form_factor_stage.h"
#include "radiosity/pipeline/iteration.h"
#include "radiosity/pipeline/kept_factors_stage.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/pipeline/resource_limits.h"
#include "radiosity/pipeline/shadow_ray_direct_irradiance.h"
#include "radiosity/pipeline/solve_stages.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/solvers/solver_factory.h"
#include "radiosity/visibility/triangle_set_caster.h"

namespace rad {
namespace {

using Clock = std::chrono::steady_clock;

// An element's identity across meshes: its material and the exact bits of its corners. Uniform
// meshing is deterministic, so a polygon that did not change meshes into the same elements.
std::string elementKey(int material, const std::array<Eigen::Vector3d, 3>& corners) {
  std::string key(sizeof(int) + 9 * sizeof(double), '\0');
  std::memcpy(key.data(), &material, sizeof(int));
  for (int c = 0; c < 3; ++c)
    std::memcpy(key.data() + sizeof(int) + 3 * c * sizeof(double), corners[c].data(),
                3 * sizeof(double));
  return key;
}

// Per new element, the kept element it is (or -1): matched by key, each kept element at most once.
std::vector<int> matchElements(const KeptFactors& kept, const PatchMesh& mesh) {
  std::unordered_multimap<std::string, int> old;
  old.reserve(kept.corners.size());
  for (size_t i = 0; i < kept.corners.size(); ++i)
    old.emplace(elementKey(kept.material[i], kept.corners[i]), static_cast<int>(i));
  std::vector<int> match(static_cast<size_t>(mesh.elementCount()), -1);
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const auto found = old.find(elementKey(mesh.material(e), mesh.corners(e)));
    if (found == old.end()) continue;
    match[static_cast<size_t>(e)] = found->second;
    old.erase(found);
  }
  return match;
}

bool sameArea(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(a, b); }

// Whether the scene's lights are, bit for bit, those the kept solve cast its direct light from
// (a kept file without their fingerprint, from before it was kept, cannot say).
bool lightsAsKept(const KeptFactors& kept, const Scene& scene) {
  return !kept.lightsFingerprint.empty() &&
         kept.lightsFingerprint == keptLightsFingerprint(scene.lights);
}

// Per light, the kept E_d of the elements whose shadow rays to it cannot meet the edit (matched,
// with the same exposed area, so the same strata and rays), `region` holding its old and new
// triangles. None when the lights changed: a lamp moved or made brighter in the lights file
// changes every element's E_d from it.
std::vector<KnownIrradiance> directLightTheEditLeaves(const KeptFactors& kept,
                                                      const Solution& solution,
                                                      const std::vector<int>& match,
                                                      const TriangleSetCaster& region) {
  const PatchMesh& mesh = *solution.mesh;
  const int n = mesh.elementCount();
  // Far beyond the rays' lift-off (RayCaster::surfaceOffset, 1e-5 of the scene's size or less).
  const double margin = 1e-4 * mesh.boundsDiagonal();
  const bool sameLights = lightsAsKept(kept, solution.scene);
  if (!sameLights)
    logInfo(
        "update: the lights are not the kept solve's (changed in the lights file, or not "
        "recorded): every element's direct light is cast again");
  const EditBox box{region.boundsMin(), region.boundsMax()};
  std::vector<KnownIrradiance> known(solution.scene.lights.size());
  for (size_t l = 0; l < known.size(); ++l) {
    KnownIrradiance& k = known[l];
    k.value.assign(static_cast<size_t>(n), Rgb());
    k.known.assign(static_cast<size_t>(n), 0);
    if (!sameLights) continue;
    tbb::parallel_for(0, n, [&](int e) {
      const int old = match[static_cast<size_t>(e)];
      if (old < 0 || !sameArea(solution.problem.area[e], kept.area[static_cast<size_t>(old)]))
        return;
      // Without an edit (nothing moved) every matched element's rays are as they were.
      if (!region.empty() &&
          shadowRaysMayMeet(solution.scene.lights[l], mesh.corners(e), mesh.normal(e), box, margin))
        return;
      k.value[static_cast<size_t>(e)] = kept.lightIrradiance[l][static_cast<size_t>(old)];
      k.known[static_cast<size_t>(e)] = 1;
    });
  }
  return known;
}

// The buried cells of the edited mesh: an element that stayed put keeps the ones it had (`kept`,
// per kept element) where none of its probe rays can meet the edit's bounds; the others are
// probed again. `keptCount` counts the elements that kept theirs.
ElementExposure exposureTheEditLeaves(const SolveOptions& options, const PatchMesh& mesh,
                                      const RayCaster& rays, const std::vector<int>& match,
                                      const std::vector<uint64_t>* kept,
                                      const TriangleSetCaster& region, int& keptCount) {
  if (!kept || options.formFactors != FormFactorMethod::Hemisphere)
    return solveExposure(options, mesh, rays);
  const int n = mesh.elementCount();
  const double margin = 1e-4 * mesh.boundsDiagonal();  // as the direct light's (above)
  const EditBox box{region.boundsMin(), region.boundsMax()};
  std::vector<uint64_t> known(static_cast<size_t>(n), 0);
  std::vector<char> isKnown(static_cast<size_t>(n), 0);
  tbb::parallel_for(0, n, [&](int e) {
    const int old = match[static_cast<size_t>(e)];
    if (old < 0) return;
    if (!region.empty()) {
      const auto corners = mesh.corners(e);
      for (const Eigen::Vector3d& d : ElementExposure::probeDirections(mesh.normal(e)))
        if (raysAlongMayMeet(corners, d, box, margin)) return;
    }
    known[static_cast<size_t>(e)] = (*kept)[static_cast<size_t>(old)];
    isKnown[static_cast<size_t>(e)] = 1;
  });
  keptCount = static_cast<int>(std::count(isKnown.begin(), isKnown.end(), 1));
  return ElementExposure(mesh, rays, known, isKnown);
}

// The kept solve and the previous solution belong together, and the scene stops rays as it did.
void checkKeptSolveFits(const KeptFactors& kept, const std::string& keptPath,
                        const PreviousSolution& previous, const Scene& scene) {
  const size_t n = kept.area.size();
  if (previous.radiosity.size() != n ||
      (!previous.buriedCells.empty() && previous.buriedCells.size() != n) ||
      (!previous.directIrradiance.empty() && previous.directIrradiance.size() != n))
    throw InputError(keptPath, 0,
                     "the previous solution has " + std::to_string(previous.radiosity.size()) +
                         " elements, the kept factors " + std::to_string(kept.area.size()) +
                         ": not the same solve");
  if (kept.lightIrradiance.size() != scene.lights.size())
    throw InputError(keptPath, 0, "changed while it was read: run update again");
  // A material turned two-sided or given a cut-out stops other rays with no geometry moved: no
  // edit region would hold the change.
  for (const auto& [name, visibility] : keptMaterialVisibility(scene)) {
    const auto was = kept.materialVisibility.find(name);
    if (was != kept.materialVisibility.end() && was->second != visibility)
      throw InputError(keptPath, 0,
                       "material '" + name +
                           "' stops rays differently than when this solve was kept (its "
                           "two-sidedness, cut-out or kind changed): update follows geometry "
                           "edits; solve --keep-factors again");
  }
}

// Which elements stayed put, and the region of the edit: the moved or added elements where they
// are now, and the kept elements no longer there where they were.
struct EditRegion {
  std::vector<int> match;          // per element: the kept element it is, or -1
  std::vector<int> newIndexOfOld;  // per kept element: the element it is now, or -1
  std::vector<char> moved;         // per element: not in the kept mesh
  std::vector<std::array<Eigen::Vector3d, 3>> region, oldPlace;
};

EditRegion findEdit(const KeptFactors& kept, const PatchMesh& mesh, SolveReport::Update& update) {
  const int n = mesh.elementCount();
  EditRegion edit;
  edit.match = matchElements(kept, mesh);
  edit.newIndexOfOld.assign(kept.area.size(), -1);
  edit.moved.assign(static_cast<size_t>(n), 0);
  for (int e = 0; e < n; ++e) {
    if (edit.match[static_cast<size_t>(e)] >= 0) {
      edit.newIndexOfOld[static_cast<size_t>(edit.match[static_cast<size_t>(e)])] = e;
    } else {
      edit.moved[static_cast<size_t>(e)] = 1;
      edit.region.push_back(mesh.corners(e));
    }
  }
  update.moved = static_cast<int>(edit.region.size());
  for (size_t i = 0; i < edit.newIndexOfOld.size(); ++i)
    if (edit.newIndexOfOld[i] < 0) {
      edit.region.push_back(kept.corners[i]);
      edit.oldPlace.push_back(kept.corners[i]);
      ++update.removed;
    }
  logInfo("update: " + std::to_string(n) + " elements, " + std::to_string(update.moved) +
          " moved or added, " + std::to_string(update.removed) + " moved or removed");
  return edit;
}

void noteProbeRays(const ElementExposure& exposure, bool hadBuriedCells, int elements,
                   SolveReport& report) {
  report.exposureProbeRays = exposure.probeRays();
  if (hadBuriedCells)
    logInfo("buried cells: " + std::to_string(report.update.buriedCellsKept) + " of " +
            std::to_string(elements) + " elements kept from before the edit, " +
            std::to_string(exposure.probeRays()) + " probe rays");
}

// What became of the kept rows of the elements that stayed put with the same exposed area and
// ray budget (the candidates): per element, whether its row was brought up to date (`reuse`),
// from which kept row (`keptFrom`), how its counts change, and its rays changed and tested.
struct KeptRowsTried {
  std::vector<int> candidates;
  uint64_t candidateRays = 0;
  std::vector<char> reuse;
  std::vector<int> keptFrom;
  std::vector<RowChanges> changes;
  std::vector<int> changedRays, raysTested;
};

KeptRowsTried tryKeptRows(const KeptFactors& kept, const EditRegion& edit,
                          const HemisphereFormFactors::Edit& casters,
                          const std::vector<int>& rayMultipliers, const RadiosityProblem& problem,
                          const FormFactorStage& formFactors, SolveReport::Update& update) {
  const std::vector<int>& match = edit.match;
  const auto n = static_cast<size_t>(problem.size());
  KeptRowsTried tried;
  tried.reuse.assign(n, 0);
  tried.keptFrom.assign(n, -1);
  tried.changes.resize(n);
  tried.changedRays.assign(n, 0);
  tried.raysTested.assign(n, 0);
  for (int e = 0; e < problem.size(); ++e) {
    const int old = match[static_cast<size_t>(e)];
    if (old < 0) continue;
    if (!sameArea(problem.area[e], kept.area[static_cast<size_t>(old)]) ||
        rayMultipliers[e] != kept.rayMultiplier[static_cast<size_t>(old)]) {
      ++update.rowsOtherChange;
      continue;
    }
    tried.candidates.push_back(e);
  }
  for (int e : tried.candidates) tried.candidateRays += formFactors.hemisphere().raysForRow(e);
  Progress progress("rays of the kept rows examined", tried.candidateRays, "rays");
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, tried.candidates.size(), 16),
      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t k = range.begin(); k != range.end(); ++k) {
          const int e = tried.candidates[k];
          const int old = match[static_cast<size_t>(e)];
          const KeptRowTable::RowView keptRow = kept.rows.view(static_cast<size_t>(old));
          // Its factor to target t (new numbering): t's kept index in the kept row.
          auto keptFactor = [&](int t) {
            const int was = match[static_cast<size_t>(t)];
            const int* end = keptRow.targets + keptRow.count;
            const int* at = std::lower_bound(keptRow.targets, end, was);
            return was >= 0 && at != end && *at == was ? keptRow.values[at - keptRow.targets] : 0.0;
          };
          if (formFactors.hemisphere().updateRow(e, keptFactor, keptRow.escaped,
                                                 tried.changes[static_cast<size_t>(e)], casters,
                                                 tried.changedRays[e], tried.raysTested[e])) {
            tried.reuse[static_cast<size_t>(e)] = 1;
            // The row goes from the kept table to the new one directly, its changes merged in;
            // the stage holds an empty stand-in meanwhile.
            tried.keptFrom[static_cast<size_t>(e)] = old;
          }
          progress.advance(formFactors.hemisphere().raysForRow(e));
        }
      });
  progress.finish(std::to_string(tried.candidates.size()) + " rows");
  update.raysOfKeptRows = tried.candidateRays;
  return tried;
}

// Counts the rows reused as they were, updated ray by ray and cast again, and logs them.
void countKeptRows(const KeptRowsTried& tried, int elements, double seconds,
                   SolveReport::Update& update) {
  for (int e : tried.candidates) {
    update.raysTested += static_cast<uint64_t>(tried.raysTested[e]);
    if (!tried.reuse[static_cast<size_t>(e)]) {
      ++update.rowsOtherChange;  // a tie at float precision: cast again
    } else if (tried.changedRays[e] > 0) {
      ++update.rowsUpdated;
      update.raysChanged += static_cast<uint64_t>(tried.changedRays[e]);
    } else {
      ++update.rowsReused;
    }
  }
  logInfo("update: " + std::to_string(update.rowsReused) + " rows reused as they were, " +
          std::to_string(update.rowsUpdated) + " updated ray by ray (" +
          std::to_string(update.raysChanged) + " rays changed their hit; " +
          std::to_string(update.raysTested) + " of their " + std::to_string(update.raysOfKeptRows) +
          " rays made and tested, the others pointing away from the edit), " +
          std::to_string(elements - update.rowsReused - update.rowsUpdated) + " cast again (" +
          std::to_string(update.moved) + " moved or new, " +
          std::to_string(update.rowsOtherChange) +
          " with another exposed area or ray budget); in " + formatNumber(seconds) + " s");
}

// Rows: a kept row is brought up to date ray by ray when its element stayed put with the same
// exposed area and ray budget; the others are cast again. Returns the new table, the kept rows
// taken over renumbered with their changes merged in.
KeptRowTable updateKeptRows(const KeptFactors& kept, const EditRegion& edit,
                            const HemisphereFormFactors::Edit& casters,
                            const std::vector<int>& rayMultipliers, const RadiosityProblem& problem,
                            FormFactorStage& formFactors, SolveReport::Update& update) {
  const auto t = Clock::now();
  const KeptRowsTried tried =
      tryKeptRows(kept, edit, casters, rayMultipliers, problem, formFactors, update);
  countKeptRows(tried, problem.size(), secondsSince(t), update);
  // Empty stand-ins for the rows taken over: they go from the kept table to the new one.
  formFactors.adoptRows(std::vector<FormFactorRow>(static_cast<size_t>(problem.size())),
                        tried.reuse);
  return KeptRowTable(formFactors.takeAllRows(), kept.rows, tried.keptFrom, edit.newIndexOfOld,
                      tried.changes);
}

// The buried cells the kept rows were cast with, per element now (the kept solve's, as the previous
// elements.csv holds them), and the elements that stayed put with other cells now: a row counts a
// ray landing in a buried cell of its target as lost, so the rays reaching those elements are
// examined as rays meeting the edit are. Without the kept cells, the cells now stand for them.
struct CellsBefore {
  std::unique_ptr<ElementExposure> exposure;  // null: as now
  std::vector<std::array<Eigen::Vector3d, 3>> changed;
};

CellsBefore buriedCellsBefore(const PatchMesh& mesh, const std::vector<int>& match,
                              const ElementExposure& now, const std::vector<uint64_t>& previous) {
  CellsBefore before;
  if (previous.empty()) return before;
  std::vector<uint64_t> cells(static_cast<size_t>(mesh.elementCount()));
  for (int e = 0; e < mesh.elementCount(); ++e) {
    const int old = match[static_cast<size_t>(e)];
    cells[static_cast<size_t>(e)] =
        old >= 0 ? previous[static_cast<size_t>(old)] : now.buriedCells(e);
    if (cells[static_cast<size_t>(e)] != now.buriedCells(e))
      before.changed.push_back(mesh.corners(e));
  }
  before.exposure = std::make_unique<ElementExposure>(mesh, std::move(cells));
  return before;
}

// Whether the update found nothing that the solution depends on changed: no element moved, was
// added or removed, every row and every light's E_d was kept, and the materials are as solved.
bool editChangedNothing(const KeptFactors& kept, const EditRegion& edit, const Solution& solution,
                        const SolveReport::Update& update) {
  const int n = solution.mesh->elementCount();
  return edit.region.empty() && update.rowsReused == n &&
         update.directLightKept ==
             static_cast<int64_t>(n) * static_cast<int64_t>(solution.scene.lights.size()) &&
         !kept.materialsFingerprint.empty() &&
         kept.materialsFingerprint == keptMaterialsFingerprint(solution.scene);
}

// The previous solution as it is, B and E_d, when the edit changed nothing: the kept solve's
// answer, which a gathering solve from it would move by the difference between its solver's
// estimate and the kept solver's (a progressive solve's rows are used the other way round).
void keepPreviousSolution(const KeptFactors& kept, const PreviousSolution& previous,
                          const std::vector<int>& match, Solution& solution, SolveReport& report) {
  const size_t n = match.size();
  solution.radiosity.resize(n);
  solution.directIrradiance.resize(n);
  for (size_t e = 0; e < n; ++e) {
    solution.radiosity[e] = previous.radiosity[static_cast<size_t>(match[e])];
    solution.directIrradiance[e] = previous.directIrradiance[static_cast<size_t>(match[e])];
  }
  report.stoppedBy = StopReason::Tolerance;
  report.converged = true;
  report.iterations = 0;
  report.solverName = solverKindName(kept.options.solver);  // whose answer it is
  report.skip("solving again", "the update found no edit: the kept solution stands");
}

// Progressive shooting, Gauss–Seidel or Jacobi from the previous solution (new elements from their
// emission): unchanged where the edit changed nothing.
void solveFromPrevious(const std::vector<Rgb>& previous, const std::vector<int>& match,
                       const SolveOptions& options, KeptFactors& next,
                       const IterationLimits& limits, Solution& solution, SolveReport& report) {
  std::vector<Rgb> guess = solution.problem.emission;
  for (size_t e = 0; e < match.size(); ++e)
    if (match[e] >= 0) guess[e] = previous[static_cast<size_t>(match[e])];
  KeptRows keptRows(next);
  // The solver borrows the rows' matrix and gives it back for factors.bin (copying 35 million
  // factors took seconds).
  const std::unique_ptr<Solver> solver = makeSolver(options.solver, solution.problem, keptRows,
                                                    [&] { return next.rows.lendMatrix(); });
  auto* gathering = dynamic_cast<GatheringSolver*>(solver.get());
  auto* shooting = dynamic_cast<ProgressiveSolver*>(solver.get());
  RAD_CHECK(gathering != nullptr || shooting != nullptr);
  if (shooting)
    shooting->startFrom(guess);
  else
    gathering->startFrom(std::move(guess));
  solveToLimits(*solver, limits, false, keptLightsIrradiance(next), solution,
                report);  // hemisphere rows: no point values
  if (gathering) next.rows.returnMatrix(gathering->releaseMatrix());
}

}  // namespace

bool continuesFromASolution(SolverKind kind) {
  return kind == SolverKind::Progressive || kind == SolverKind::GaussSeidel ||
         kind == SolverKind::Jacobi;
}

SolveResult updateKeptSolve(const KeptFactors& kept, const std::string& keptPath,
                            const PreviousSolution& previous, const SolveOptions& solverOptions) {
  return finishUpdate(startUpdate(kept, keptPath, solverOptions), kept, keptPath, previous);
}

UpdateStart startUpdate(const KeptFactors& header, const std::string& keptPath,
                        const SolveOptions& solverOptions) {
  UpdateStart started;
  started.start = Clock::now();
  if (!continuesFromASolution(solverOptions.solver))
    throw InputError(
        "update continues from the previous solution, which --solver progressive, gauss-seidel "
        "and jacobi can (" +
        solverKindName(solverOptions.solver) + " cannot)");
  // The kept solve's mesh and ray options, with its element size fixed: an added object must not
  // change the size the scene's default would pick, or no element would stay put.
  SolveOptions& options = started.options;
  options = withSolverOf(header.options, solverOptions);
  options.scenePath = header.scenePath;
  options.lights = header.lightInput;
  options.maxArea = 0;
  options.targetElements = 0;
  options.elementSize = header.elementEdge;
  options.keepFactors = true;
  validateSolveOptions(options);

  Solution& solution = started.result.solution;
  SolveReport& report = started.result.report;
  const ThreadLimit threads = limitSolveThreads(options, report);
  const auto t = Clock::now();
  solution.scene =
      loadScene(options.scenePath, options.lights, options.twoSided, options.unreadableTextures);
  report.times.load = secondsSince(t);
  checkSceneLimits(solution.scene);
  requireEmitter(solution.scene);
  if (solution.scene.hasSpecular())
    throw InputError(
        keptPath, 0,
        "the scene has mirrors or glass, whose rows continue past their first hit: "
        "update cannot tell which of them an edit changes; solve --keep-factors again");
  if (solution.scene.lights.size() != header.lightTypes.size())
    throw InputError(keptPath, 0,
                     "the scene has " + std::to_string(solution.scene.lights.size()) +
                         " lights, the kept solve had " + std::to_string(header.lightTypes.size()) +
                         ": update follows geometry edits; solve --keep-factors again");

  meshStage(solution, options, report);
  return started;
}

SolveResult finishUpdate(UpdateStart started, const KeptFactors& kept, const std::string& keptPath,
                         const PreviousSolution& previous) {
  const SolveOptions& options = started.options;
  checkKeptSolveFits(kept, keptPath, previous, started.result.solution.scene);
  SolveResult result = std::move(started.result);
  Solution& solution = result.solution;
  SolveReport& report = result.report;
  SolveReport::Update& update = report.update;
  update.keptFactors = keptPath;
  const ThreadLimit threads = limitSolveThreads(options, report);
  const PatchMesh& mesh = *solution.mesh;
  const EditRegion edit = findEdit(kept, mesh, update);

  auto t = Clock::now();
  const RayCaster rays(mesh, solution.scene);
  report.times.bvh = secondsSince(t);
  const TriangleSetCaster regionCaster(edit.region, rays.centre(), mesh.boundsDiagonal()),
      oldCaster(edit.oldPlace, rays.centre(), mesh.boundsDiagonal());
  solution.exposure = std::make_shared<const ElementExposure>(
      exposureTheEditLeaves(options, mesh, rays, edit.match,
                            previous.buriedCells.empty() ? nullptr : &previous.buriedCells,
                            regionCaster, update.buriedCellsKept));
  const ElementExposure& exposure = *solution.exposure;  // for elements.csv, as a solve keeps it
  noteProbeRays(exposure, !previous.buriedCells.empty(), mesh.elementCount(), report);
  solution.problem = makeProblem(solution.scene, mesh, &exposure);
  // The lights' first shot: an element that stayed put, with the same exposed area, whose shadow
  // rays to a light cannot meet the edit keeps the E_d the kept solve computed.
  const std::vector<KnownIrradiance> knownDirect =
      directLightTheEditLeaves(kept, solution, edit.match, regionCaster);
  for (const KnownIrradiance& k : knownDirect)
    update.directLightKept += std::count(k.known.begin(), k.known.end(), 1);
  std::vector<int> rayMultipliers;
  std::shared_ptr<KeptFactors> next = keepLightsApart(
      solution, rays, options, exposure, report.elementSize, rayMultipliers, report, &knownDirect);

  FormFactorStage formFactors(solution.scene, mesh, rays, solution.problem, options, &exposure,
                              rayMultipliers);
  const RayCaster withoutMoved(mesh, solution.scene, edit.moved);
  const CellsBefore cellsBefore =
      buriedCellsBefore(mesh, edit.match, exposure, previous.buriedCells);
  std::vector<std::array<Eigen::Vector3d, 3>> rowRegion = edit.region;
  rowRegion.insert(rowRegion.end(), cellsBefore.changed.begin(), cellsBefore.changed.end());
  const TriangleSetCaster rowRegionCaster(rowRegion, rays.centre(), mesh.boundsDiagonal());
  next->rows = updateKeptRows(
      kept, edit,
      {rowRegionCaster, oldCaster, edit.moved, withoutMoved, cellsBefore.exposure.get()},
      rayMultipliers, solution.problem, formFactors, update);
  next->fingerprint = keptFactorsFingerprint(solution.scene, options);
  next->options = options;

  t = Clock::now();
  if (!previous.directIrradiance.empty() && editChangedNothing(kept, edit, solution, update))
    keepPreviousSolution(kept, previous, edit.match, solution, report);
  else
    solveFromPrevious(previous.radiosity, edit.match, options, *next,
                      iterationLimits(options, mesh.elementCount(), started.start), solution,
                      report);
  if (solution.directIrradiance.empty())  // rows through mirrors and glass
    solution.directIrradiance =
        directIrradianceByShadowRays(solution, solution.problem, keptLightsIrradiance(*next), rays,
                                     exposure, options, report.raysCast);
  formFactors.report(report, options.solver);
  report.shooters = mesh.elementCount();
  report.times.solve = secondsSince(t);
  report.times.total = secondsSince(started.start);
  result.kept = std::move(next);
  return result;
}

SolveOptions updatedSolutionOptions(const KeptFactors& kept, const SolveResult& updated) {
  const SolveOptions& fixed = updated.kept->options;
  const PatchMesh& mesh = *updated.solution.mesh;
  const ElementSizing userRule =
      decideElementSize(kept.options, mesh.totalArea(), mesh.boundsDiagonal());
  if (userRule.rule == ElementSizeRule::Elements ||
      std::abs(userRule.edge - kept.elementEdge) > 1e-9 * kept.elementEdge)
    return fixed;
  SolveOptions own = withSolverOf(kept.options, fixed);
  own.scenePath = fixed.scenePath;
  own.lights = fixed.lights;
  return own;
}

}  // namespace rad
