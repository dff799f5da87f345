#include "radiosity/pipeline/form_factor_stage.h"

#include <string>

#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/solvers/gathering_solvers.h"

namespace rad {

FormFactorStage::FormFactorStage(const Scene& scene, const PatchMesh& mesh, const RayCaster& rays,
                                 const RadiosityProblem& problem, const SolveOptions& options,
                                 const ElementExposure* exposure, std::vector<int> rayMultipliers)
    : mesh_(mesh),
      problem_(problem),
      hemisphere_(
          mesh, rays,
          {options.raysPerElement, options.seed,
           rayMultipliers.empty() ? emitterRayMultipliers(problem) : std::move(rayMultipliers),
           scene.hasSpecular() ? specularSurfaces(scene, mesh) : std::vector<SpecularSurface>(),
           exposure}),
      cache_(hemisphere_) {
  if (options.formFactors != FormFactorMethod::Analytic) return;
  analytic_ = std::make_unique<AnalyticPatchShots>(
      mesh, rays, AnalyticOptions{options.receiverPoints, options.shadowRays, options.seed});
  // Shadow boundaries worth refining are those of the emitters' direct light.
  std::vector<char> emitting(mesh.shooterCount(), 0);
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (problem.emission[e].maxComponent() > 0) emitting[mesh.shooter(e)] = 1;
  analytic_->setShadowCasters(std::move(emitting));
}

ShotRows& FormFactorStage::shots() {
  return analytic_ ? static_cast<ShotRows&>(*analytic_) : cache_;
}

SparseRows FormFactorStage::gatheringMatrix() {
  if (analytic_) {
    Progress progress("form factors", analytic_->shooterCount(), "patches");
    SparseRows f = analytic_->gatheringMatrix(&progress);
    progress.finish();
    return f;
  }
  uint64_t totalRays = 0;
  for (int e = 0; e < mesh_.elementCount(); ++e) totalRays += hemisphere_.raysForRow(e);
  Progress progress("form factors", totalRays, "rays");
  SparseRows f = gatherMatrix(problem_, cache_, &progress);
  progress.finish(std::to_string(cache_.rowsComputed()) + " rows");
  return f;
}

std::vector<FormFactorRow> FormFactorStage::takeAllRows() {
  RAD_CHECK_MSG(analytic_ == nullptr, "kept factors are hemisphere rows");
  uint64_t missing = 0;
  for (int e = 0; e < mesh_.elementCount(); ++e)
    if (!cache_.hasRow(e)) missing += hemisphere_.raysForRow(e);
  Progress progress("rows kept", missing, "rays");
  std::vector<FormFactorRow> rows = cache_.takeAllRows(&progress);
  progress.finish(std::to_string(rows.size()) + " rows");
  return rows;
}

void FormFactorStage::adoptRows(std::vector<FormFactorRow>&& rows,
                                const std::vector<char>& reused) {
  RAD_CHECK_MSG(analytic_ == nullptr, "kept factors are hemisphere rows");
  RAD_CHECK_EQ(rows.size(), reused.size());
  for (size_t e = 0; e < rows.size(); ++e)
    if (reused[e]) {
      cache_.adopt(static_cast<int>(e), std::move(rows[e]));
      ++adoptedRows_;
      adoptedRays_ += hemisphere_.raysForRow(static_cast<int>(e));
    }
}

const std::vector<char>& FormFactorStage::partlyShadowed() const {
  RAD_CHECK_MSG(analytic_ != nullptr, "shadow boundaries are known to analytic factors only");
  return analytic_->partlyShadowed();
}

void FormFactorStage::meshChanged(const std::vector<int>& changed) {
  RAD_CHECK_MSG(analytic_ != nullptr, "refinement needs analytic form factors");
  analytic_->meshChanged(changed);
}

std::array<double, 3> FormFactorStage::pointFactorsCached(int element, int shooter) const {
  return analytic_->elementToShooterAtPointsCached(element, shooter);
}

void FormFactorStage::report(SolveReport& report, SolverKind solver) const {
  report.shooters = analytic_ ? analytic_->shooterCount() : cache_.shooterCount();
  report.rowsComputed = analytic_ ? analytic_->rowsComputed() : cache_.rowsComputed();
  report.specularRays = analytic_ ? 0 : hemisphere_.specularRays();
  report.raysCast = analytic_ ? analytic_->raysCast() : cache_.raysCast() + report.specularRays;
  report.times.formFactors = analytic_ ? analytic_->seconds() : cache_.seconds();
  if (adoptedRows_ > 0)
    report.skip("form-factor rows of " + std::to_string(adoptedRows_) + " elements (" +
                    std::to_string(adoptedRays_) + " rays saved)",
                "kept from the solve before the edit, brought up to date ray by ray");
  if (report.rowsComputed + adoptedRows_ < report.shooters) {
    // Hemisphere rows have a known ray count each: report what skipping them saved.
    uint64_t raysSaved = 0;
    if (!analytic_)
      for (int e = 0; e < mesh_.elementCount(); ++e)
        if (!cache_.hasRow(e)) raysSaved += hemisphere_.raysForRow(e);
    report.skip(
        "form-factor rows of " + std::to_string(report.shooters - report.rowsComputed) +
            (analytic_ ? " patches" : " elements (" + std::to_string(raysSaved) + " rays saved)"),
        solver == SolverKind::Progressive ? "they never held unshot power worth shooting"
                                          : "black elements pass no light on");
  }
  if (analytic_)
    report.skip("shadow rays between element–patch pairs facing away from each other or coplanar",
                "they cannot exchange light; the pairs are not counted");
}

}  // namespace rad
