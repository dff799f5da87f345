#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/formfactors/analytic_patch_shots.h"
#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The form factors of a meshed scene, as the options choose them: hemisphere rows per element
// (ray cast, cached on first use; emitters get rays by their share of the power), or analytic
// element-to-patch factors with shadow rays (patches marked on the mesh shoot to its elements).
// Either way the solvers read them through shots() (lazily) or gatheringMatrix() (all at once).
// Holds references to the mesh and the ray caster, which must outlive it.
class FormFactorStage {
 public:
  // `exposure` (optional, must outlive the stage): hemisphere rows shoot from the exposed parts
  // of elements only.
  // `rayMultipliers`: each emitter row's rays relative to an average row; empty: from `problem`
  // (emitterRayMultipliers).
  FormFactorStage(const Scene& scene, const PatchMesh& mesh, const RayCaster& rays,
                  const RadiosityProblem& problem, const SolveOptions& options,
                  const ElementExposure* exposure = nullptr, std::vector<int> rayMultipliers = {});

  ShotRows& shots();
  // Every row at once, for the gathering solvers (with a progress line).
  Eigen::SparseMatrix<double, Eigen::RowMajor> gatheringMatrix();
  bool analytic() const { return analytic_ != nullptr; }
  // The hemisphere rows' method (also with analytic factors: the viewer draws its rays).
  const HemisphereFormFactors& hemisphere() const { return hemisphere_; }

  // Every element's hemisphere row (computing those not cached yet, in parallel), moved out of
  // the cache, which is spent: for kept factors, after the solve.
  std::vector<FormFactorRow> takeAllRows();
  // Rows known still to hold (`update`: kept rows whose rays meet nothing that moved): reused[e]
  // set means rows[e] is element e's row, taken into the cache as if computed.
  void adoptRows(std::vector<FormFactorRow>&& rows, const std::vector<char>& reused);
  // Adaptive refinement (analytic factors): elements that a shadow boundary of an emitting patch
  // crosses; updating the rows after `changed` elements were split; the point factors of an
  // element to a shooter, from its cached row.
  const std::vector<char>& partlyShadowed() const;
  void meshChanged(const std::vector<int>& changed);
  std::array<double, 3> pointFactorsCached(int element, int shooter) const;

  // For the report: shooters, rows and rays computed, wall time spent on rows; notes the rows
  // never computed (and the rays that saved) and the pairs never traced.
  void report(SolveReport& report, SolverKind solver) const;

 private:
  const PatchMesh& mesh_;
  const RadiosityProblem& problem_;  // updated in place by refinement
  HemisphereFormFactors hemisphere_;
  FormFactorCache cache_;
  std::unique_ptr<AnalyticPatchShots> analytic_;
  int adoptedRows_ = 0;  // rows adoptRows took in, and the rays they would have cost
  uint64_t adoptedRays_ = 0;
};

}  // namespace rad
