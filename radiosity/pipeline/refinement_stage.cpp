#include "radiosity/pipeline/refinement_stage.h"

#include <array>
#include <string>
#include <vector>

#include "radiosity/core/check.h"
#include "radiosity/core/log.h"
#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/solvers/refinable_solver.h"

namespace rad {

AdaptiveRefinement::AdaptiveRefinement(const SolveOptions& options, const PatchMesh& uniformMesh)
    : enabled_(options.refineThreshold > 0),
      passes_(options.refinePasses),
      startElements_(uniformMesh.elementCount()),
      receiverPoints_(options.receiverPoints) {
  // The budget, and the smallest element: 1/16 of the area elements would have if the whole
  // budget were spread evenly, so shadow edges can be resolved well below the even spacing.
  const int budget = options.maxElements > 0 ? options.maxElements : 8 * startElements_;
  options_ = {options.refineThreshold,
              options.minArea > 0 ? options.minArea : uniformMesh.totalArea() / budget / 16,
              budget};
}

bool AdaptiveRefinement::refine(int pass, Solution& solution, FormFactorStage& formFactors,
                                DirectLightStage& directLight, Solver& solver,
                                SolveReport& report) {
  if (!enabled_ || pass == passes_) return false;
  auto* refinable = dynamic_cast<RefinableSolver*>(&solver);
  RAD_CHECK_MSG(refinable != nullptr, "adaptive refinement needs a refinable solver");
  PatchMesh& mesh = *solution.mesh;
  std::vector<int> selected;
  if (receiverPoints_ == 3) {
    // The receiver points resolve a linear field per element: refine by what is displayed
    // against them.
    const auto& atPoints = refinable->pointSolution();
    std::vector<std::array<double, 3>> luminance(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e)
      for (int k = 0; k < 3; ++k) luminance[e][k] = atPoints[e][k].luminance();
    selected = selectForRefinement(mesh, luminance, formFactors.partlyShadowed(), options_);
  } else {
    std::vector<double> luminance(mesh.elementCount());
    for (int e = 0; e < mesh.elementCount(); ++e) luminance[e] = solver.solution()[e].luminance();
    selected = selectForRefinement(mesh, luminance, formFactors.partlyShadowed(), options_);
  }
  unrefined_ = mesh.elementCount() - static_cast<int>(selected.size());
  if (selected.empty()) return false;
  const int before = mesh.elementCount();
  const int target =
      refinementTarget(startElements_, options_.maxElements, pass, std::max(1, passes_));
  const std::vector<int> changed = refineElements(mesh, selected, options_, target);
  solution.problem = makeProblem(solution.scene, mesh);
  directLight.meshChanged(changed, solution.problem);
  formFactors.meshChanged(changed);
  refinable->elementsChanged(changed,
                             [&](int e, int s) { return formFactors.pointFactorsCached(e, s); });
  ++report.refinementPasses;
  logInfo("refinement pass " + std::to_string(pass + 1) + ": " + std::to_string(selected.size()) +
          " candidates, " + std::to_string(before) + " → " + std::to_string(mesh.elementCount()) +
          " elements");
  if (mesh.elementCount() >= options_.maxElements) {
    report.skip("further refinement", "the element budget (--max-elements) is reached");
    return false;
  }
  return true;
}

void AdaptiveRefinement::finish(SolveReport& report) const {
  if (unrefined_ > 0)
    report.skip(
        "splitting " + std::to_string(unrefined_) + " elements in the last refinement pass",
        "the radiance displayed over them is within the threshold of their solved value and no "
        "emitter shadow crosses them");
}

}  // namespace rad
