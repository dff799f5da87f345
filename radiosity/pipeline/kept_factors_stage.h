#pragma once

#include <memory>
#include <string>
#include <vector>

#include "radiosity/formfactors/form_factor_row.h"
#include "radiosity/formfactors/shot_rows.h"
#include "radiosity/pipeline/direct_light_stage.h"
#include "radiosity/pipeline/kept_factors.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Kept factors in a solve: what a solve keeps of itself (keepLightsApart), and what relight and
// update solve over (KeptRows, withSolverOf). Their file is kept_factors.h.

// The lights' first shot of a kept solve, all lights together: Σ_l scale_l E_d,l per element
// (`scale`: one per light, relight's overrides; empty: 1 each). Empty when there are no lights.
std::vector<Rgb> keptLightsIrradiance(const KeptFactors& kept, const std::vector<Rgb>& scale = {});

// --keep-factors: each light's first shot on its own (no lamp sampling across lights, so relight
// can scale each E_d), added to the emission; the rays per emitter row from each source's own
// shares, without ρ (sourceRayMultipliers): relight changes neither. Returns the kept factors
// without their rows (taken after the solve), with the mesh `update` compares against;
// `elementEdge` the mesh's element size S. `known` (update), one per light: E_d that stands.
std::shared_ptr<KeptFactors> keepLightsApart(Solution& solution, const RayCaster& rays,
                                             const SolveOptions& options,
                                             const ElementExposure& exposure, double elementEdge,
                                             std::vector<int>& rayMultipliers, SolveReport& report,
                                             const std::vector<KnownIrradiance>* known = nullptr);

// The kept solve's options `kept` with the solver, stopping rule, threads and output directory of
// `solver`: what relight and update solve with.
SolveOptions withSolverOf(SolveOptions kept, const SolveOptions& solver);

// The kept rows as progressive shooting reads them (elements shoot their own rows). A row is
// valid until the next call.
class KeptRows : public ShotRows {
 public:
  explicit KeptRows(const KeptFactors& kept) : kept_(kept) {}
  int shooterCount() const override { return static_cast<int>(kept_.rows.size()); }
  int shooterOf(int element) const override { return element; }
  double shooterArea(int shooter) const override { return kept_.area[shooter]; }
  const FormFactorRow& powerFractions(int shooter) override {
    row_ = kept_.rows.row(static_cast<size_t>(shooter));
    return row_;
  }
  std::string description() const override { return "kept element rows (hemisphere)"; }

 private:
  const KeptFactors& kept_;
  FormFactorRow row_;
};

}  // namespace rad
