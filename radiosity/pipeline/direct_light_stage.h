#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/lighting/light_choice.h"
#include "radiosity/pipeline/exposed_strata.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Rays per point: the sky's (or a map's) hemisphere in skyStrata² strata, a sun of non-zero
// angular diameter in sunStrata² strata over its disc. The defaults are a receiver point's.
struct DirectRays {
  int skyStrata = 8;  // even: a map's rays are skyStrata × skyStrata / 2, twice
  int sunStrata = 4;
};
// An element's mean E_d: kAreaStrata² points stratified over its area (exposed_strata.h), each
// with kAreaRays (4 × 4 sky rays, 2 × 2 over the sun): 256 sky rays per element in all, as many
// directions as the three receiver points had, now spread over the whole element.
constexpr DirectRays kAreaRays{4, 2};
// With more point and spot lights than kEveryPointLight (lighting/light_choice.h), each point
// casts one shadow ray, to a light chosen by chooseLight.

// The sum of the point and spot lights' E_d at x by that one shadow ray; `u` in [0, 1) picks it.
Rgb sampledPointLightIrradiance(const std::vector<const Light*>& lights, const RayCaster& rays,
                                const Eigen::Vector3d& x, const Eigen::Vector3d& n, double u,
                                uint64_t& raysCast);

// Direct irradiance (W·m⁻²) from one light at point `x` of a one-sided surface with unit normal
// `n` (only its front receives), shadow rays through `rays`. Point: I cosθ / r²; spot: the same
// times 0 outside the outer cone, 1 inside the inner cone, smoothstep in cos between; directional:
// E cosθ (one ray, or sunStrata² stratified over its disc when its angular diameter > 0); sky:
// π × the mean, over skyStrata² cosine-weighted rays, of the sky's radiance along those that leave
// the scene above the horizon of `up` (πL × their fraction for a uniform sky); environment and CIE
// clear sky: skyStrata² / 2 rays by the map's luminance and as many cosine-weighted, combined by
// the balance heuristic. `key` seeds the stratified jitter; `raysCast` counts the rays.
Rgb directIrradiance(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                     const Eigen::Vector3d& n, uint64_t key, uint64_t& raysCast,
                     const DirectRays& count = DirectRays{});

// The first shot of the lights besides emissive polygons (point, spot, directional, sky,
// environment): each element's mean direct irradiance E_d over its exposed area (stratified
// points, kAreaStrata²); the reflected part ρ E_d enters the problem as emission, so the solver
// carries the interreflection on from there. Where the solution keeps B at the receiver points
// (analytic factors' Gauss points), E_d is computed there too, for the displayed variation inside
// the element. Holds references to the scene, mesh and ray caster, which must
// outlive it.
// E_d already known for some elements (update: those whose shadow rays an edit cannot meet):
// known[e] says whether value[e] stands; both one per element.
struct KnownIrradiance {
  std::vector<Rgb> value;
  std::vector<char> known;
};

class DirectLightStage {
 public:
  // With `exposure`, points in a buried part of an element are left out (with no receiver point
  // left, E_d at an exposed point of the element stands for them). With `lights` (indices into
  // scene.lights, e.g. one light group's), only those shoot; each keeps the random numbers it
  // has among all the lights.
  DirectLightStage(const Scene& scene, const PatchMesh& mesh, const RayCaster& rays,
                   const SolveOptions& options, const ElementExposure* exposure = nullptr,
                   const std::vector<size_t>* lights = nullptr);

  // Computes E_d for every element and adds ρ E_d to problem.emission; logs one line. Elements
  // `known` gives take its value and cast no ray (not with receiver points kept, RAD_CHECK).
  void apply(RadiosityProblem& problem, const KnownIrradiance* known = nullptr);
  // After refinement split the elements `changed` (problem rebuilt by makeProblem): E_d of the
  // changed elements afresh, then ρ E_d added to every element's emission again.
  void meshChanged(const std::vector<int>& changed, RadiosityProblem& problem);

  // The solver saw each element's mean E_d; where the solution keeps B at the receiver points
  // (pointRadiosity), adds ρ (E_d at the point − the receiver points' mean), so the displayed
  // solution shows how the direct light varies inside an element and its points still average
  // to the element's B.
  void addPointVariation(const RadiosityProblem& problem,
                         std::vector<std::array<Rgb, 3>>& pointRadiosity) const;

  const std::vector<Rgb>& irradiance() const { return irradiance_; }  // E_d per element
  uint64_t raysCast() const { return raysCast_; }
  // The rays cast, for summary.json.
  void report(SolveReport& report) const;

 private:
  void compute(int element);
  void addEmission(RadiosityProblem& problem) const;
  const Scene& scene_;
  const PatchMesh& mesh_;
  const RayCaster& rays_;
  const ElementExposure* exposure_;
  uint64_t seed_;
  int receiverPoints_;
  // Whether the solution keeps B at the receiver points (analytic factors, 3 points; the
  // condition keepsPointValues gives), so E_d is wanted there too.
  bool keepPoints_;
  std::vector<size_t> lights_;             // the scene's lights that shoot here
  std::vector<const Light*> pointLights_;  // the point and spot lights among them
  bool samplePointLights_;                 // more of them than kEveryPointLight
  std::vector<Rgb> irradiance_;
  std::vector<std::array<Rgb, 3>> pointIrradiance_;  // E_d at each receiver point
  std::vector<Rgb> pointMean_;                       // their mean over the exposed ones
  std::vector<uint64_t> elementRays_;
  uint64_t raysCast_ = 0;
};

}  // namespace rad
