#pragma once

#include <array>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// What a solver reached, read back once its iterations stop (every solve, light group, relight
// and update reads it here): B per element, B at the receiver points where the rows resolve them,
// and the unshot power a shooting solver still holds.
struct SolverResults {
  std::vector<Rgb> radiosity;
  // B at each element's 3 receiver points: with `pointValues` (analytic factors with 3 receiver
  // points) from a shooting solver; empty otherwise.
  std::vector<std::array<Rgb, 3>> pointRadiosity;
  std::vector<Rgb> unshot;  // per element (W); empty for a gathering solver
};
// Whether the solution keeps B at the receiver points: analytic factors with 3 receiver points,
// where a shooting solver resolves them (the direct light's variation is added there too).
bool keepsPointValues(const SolveOptions& options);
SolverResults readSolverResults(const Solver& solver, bool pointValues);

// The emitters' own emission in `problem`: its emission less the lights' ρ E_d
// (`lightsIrradiance`, one per element, or empty), 0 on elements whose material does not emit.
std::vector<Rgb> ownEmission(const Solution& solution, const RadiosityProblem& problem,
                             const std::vector<Rgb>& lightsIrradiance);

// Each element's E_d (Solution::directIrradiance) for `problem`, solved by `solver`: the lights'
// first shot `lightsIrradiance` (one per element, or empty: no lights) plus the irradiance the
// emitters' own emission sends through the solver's own form factors (Solver::irradianceFrom);
// 0 on black elements. Empty when the solver cannot tell the emitters' part apart (hierarchical
// links), or when the scene has mirrors or glass: rows that follow light through them hold what an
// emitter sends through them too, which is not the direct light the split's shadow rays see
// (directIrradianceByShadowRays instead, in shadow_ray_direct_irradiance.h).
std::vector<Rgb> directIrradianceOf(Solver& solver, const Solution& solution,
                                    const RadiosityProblem& problem,
                                    const std::vector<Rgb>& lightsIrradiance);

// readSolverResults into the solution (radiosity, pointRadiosity, unshot) and directIrradianceOf
// (with the lights' first shot `lightsIrradiance`), and the solver's name, measure, iterations
// and final progress into the report (reportSolver).
void keepSolverResults(Solver& solver, bool pointValues, const std::vector<Rgb>& lightsIrradiance,
                       Solution& solution, SolveReport& report);

}  // namespace rad
