#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/lighting/power_distribution.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The emissive polygons' direct light, by shadow rays to points on them, for a gathering solve
// whose own rays would find a small bright emitter by chance: gathering each element's light
// through 256 hemisphere rays left a room lit by its ceiling's lamp 11-17% from a path-traced
// reference per element (bench/hierarchical_scale.py), nearly all of it the lamp's direct light.
//
// The system is solved for the reflected radiosity R = B − E instead of B: with D_e the direct
// irradiance from the emitters (Σ_j F_ej E_j), R_e = ρ_e D_e + ρ_e Σ_j F_ej R_j, a radiosity
// system of the same ρ and F whose emission is ρD; then B = R + E. apply() makes that problem
// from the emissive polygons' E alone (before the lights' first shot, DirectLightStage, adds to
// it); restore() puts E back. Emitting patches larger than 5% of the scene's area
// (kLargeEmitterShare: a glowing wall, a sky dome) stay in the emission, and so do all emitters
// when the small ones together exceed that share: the links' hemisphere rays find them well, and
// light sampling by power would rarely pick the elements beside a receiver (a furnace room whose
// every surface emits: the median element 4.5% dark, some 4 times too bright).
//
// D_e is the mean over kAreaStrata² points stratified over the element's exposed area; each point
// sends `raysPerPoint` samples, an emitting element picked in proportion to its power
// emitterPower (A × E summed over the channels), the picks of one point stratified along the power
// in Morton order (so they spread over an emitter like a jittered grid). Far from the picked
// element (kFarRadii of its radii), a uniform point of it stands for it: E·A·cos·cos/(π r²) times
// the shadow ray's visibility, unbiased in a penumbra; nearer, its unoccluded point-to-triangle
// factor in closed form (bounded however near) times the visibility of a point on it (one-sided:
// only the front of an emitter emits, only the front of a receiver receives).
class EmitterFirstShot {
 public:
  // The shadow rays per element a hierarchical solve gives the emitters' direct light: half
  // --rays. With the emitters' factors in closed form only visibility is sampled, and on the
  // generated room of bench/hierarchical_scale.py at 10^4 elements and --rays 1024, 512 shadow
  // rays per element gave the same error against the path-traced reference as 1024 (1.88% and
  // 1.87%), 256 more (2.26% at --rays 512 against 2.23% with 1024).
  static int raysForSolve(int raysPerElement) { return std::max(1, raysPerElement / 2); }

  // Holds references to all four, which must outlive it. `raysPerElement`: shadow rays per element
  // in all, spread over its points.
  // `largeEmitterShare`: emitting patches above this share of the scene's area, or all when the
  // rest together exceed it, are left to the solve (1: shoot every emitter).
  static constexpr double kLargeEmitterShare = 0.05;
  EmitterFirstShot(const PatchMesh& mesh, const RayCaster& rays, const ElementExposure& exposure,
                   uint64_t seed, int raysPerElement,
                   double largeEmitterShare = kLargeEmitterShare);

  // Each small emitter's E (π Ke, makeProblem's) leaves problem.emission, and ρ D joins every
  // element's. No small emissive polygon: nothing changes.
  void apply(RadiosityProblem& problem);
  // The emission E + whatever was added since apply() (the lights' first shot), and B = R + E for
  // the solution the solver gave over R.
  void restore(RadiosityProblem& problem, std::vector<Rgb>& radiosity) const;

  bool active() const { return !emitters_.empty(); }
  int emitters() const { return static_cast<int>(emitters_.size()); }
  uint64_t raysCast() const { return raysCast_; }
  const std::vector<Rgb>& irradiance() const { return irradiance_; }  // D per element

 private:
  void sortAlongSpace();
  // Whether the segment from x (normal n) to y on an emitter (normal ny) is unoccluded.
  bool visible(const Eigen::Vector3d& x, const Eigen::Vector3d& n, const Eigen::Vector3d& y,
               const Eigen::Vector3d& ny) const;
  // D at point x of normal n, from raysPerPoint_ samples.
  Rgb directAt(const Eigen::Vector3d& x, const Eigen::Vector3d& n, Rng& rng) const;

  const PatchMesh& mesh_;
  const RayCaster& rays_;
  const ElementExposure& exposure_;
  uint64_t seed_;
  int raysPerPoint_;
  double largeEmitterShare_;
  std::vector<int> emitters_;  // emitting elements
  PowerDistribution power_;    // over emitters_, by emitterPower
  std::vector<Rgb> emission_;  // E of the emitters shot here, 0 elsewhere
  std::vector<Rgb> irradiance_;
  uint64_t raysCast_ = 0;
};

}  // namespace rad
