#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rgb.h"
#include "radiosity/pipeline/solution.h"
#include "radiosity/pipeline/solve_options.h"
#include "radiosity/scene/scene.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// Rays per receiver point: the sky's cosine-weighted hemisphere (8 × 8 strata) and a sun of
// non-zero angular diameter (4 × 4 strata over its disc).
constexpr int kSkyRays = 64;
constexpr int kSunDiscRays = 16;

// Direct irradiance (W·m⁻²) from one light at point `x` of a one-sided surface with unit normal
// `n` (only its front receives), shadow rays through `rays`. Point: I cosθ / r²; spot: the same
// times 0 outside the outer cone, 1 inside the inner cone, smoothstep in cos between; directional:
// E cosθ (one ray, or kSunDiscRays stratified over its disc when its angular diameter > 0); sky:
// π × the mean, over kSkyRays cosine-weighted rays, of the sky's radiance along those that leave
// the scene above the horizon of `up` (πL × their fraction for a uniform sky); environment and CIE
// clear sky: kSkyRays / 2 rays by the map's luminance and as many cosine-weighted, combined by the
// balance heuristic. `key` seeds the stratified jitter; `raysCast` counts the rays.
Rgb directIrradiance(const Light& light, const RayCaster& rays, const Eigen::Vector3d& x,
                     const Eigen::Vector3d& n, uint64_t key, uint64_t& raysCast);

// The first shot of the lights besides emissive polygons (point, spot, directional, sky,
// environment): the
// direct irradiance E_d at each element's receiver points (the analytic factors' Gauss points, or
// the centroid with --receiver-points 1), averaged per element; the reflected part ρ E_d enters the
// problem as emission, so the solver carries the interreflection on from there. Holds references
// to the scene, mesh and ray caster, which must outlive it.
class DirectLightStage {
 public:
  // With `exposure`, receiver points in a buried part of an element are left out (the element's
  // E_d is the mean over the others; with none left, E_d at an exposed point of the element).
  DirectLightStage(const Scene& scene, const PatchMesh& mesh, const RayCaster& rays,
                   const SolveOptions& options, const ElementExposure* exposure = nullptr);

  // Computes E_d for every element and adds ρ E_d to problem.emission; logs one line.
  void apply(RadiosityProblem& problem);
  // After refinement split the elements `changed` (problem rebuilt by makeProblem): E_d of the
  // changed elements afresh, then ρ E_d added to every element's emission again.
  void meshChanged(const std::vector<int>& changed, RadiosityProblem& problem);

  // The solver saw each element's mean E_d; where the solution keeps B at the receiver points
  // (pointRadiosity), adds ρ (E_d at the point − the mean), so the displayed solution shows how
  // the direct light varies inside an element (exact, as B is linear in E).
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
  std::vector<Rgb> irradiance_;
  std::vector<std::array<Rgb, 3>> pointIrradiance_;  // E_d at each receiver point
  std::vector<uint64_t> elementRays_;
  uint64_t raysCast_ = 0;
};

}  // namespace rad
