#pragma once

#include <vector>

#include "meshing/vertex_interpolation.h"
#include "radiosity/render/integrator.h"
#include "radiosity/render/texel_footprint.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

struct FinalGatherOptions {
  // 0: show the interpolated radiosity B/π at the first diffuse hit (preview), or with lightRays
  // > 0, the direct light by lightRays shadow rays at the hit plus the solution's indirect part
  // interpolated there (indirectFromSolution below). N > 0: direct
  // light by N shadow rays to the emitters plus N cosine-weighted gather rays into the
  // solution's reflected part (B − E)/π; the two share the direct light by multiple importance
  // sampling (a gather ray that reaches an emitter adds its MIS-weighted Ke). A gather ray that
  // lands on a diffuse surface closer than the size of the element it hits (a corner, a
  // contact) gathers once more from that point (one shadow and one cosine ray, MIS-weighted in
  // the same way) instead of taking the element's value.
  int gatherRays = 64;
  // Shadow rays per diffuse eye hit; 0: as many as gatherRays (with gatherRays 0: the preview).
  // Fewer than gatherRays pays where the gather's indirect part, not the direct light, holds most
  // of the variance (the Cornell box: docs/benchmarks.md, "Error against time"); the MIS weights
  // count the rays of each kind (power heuristic with n·pdf), so any count stays unbiased.
  int lightRays = 0;

  // The one place the two counts decide the mode (the gather, the command line's reports):
  // shadow rays per hit, lightRays or else as many as gatherRays;
  int shadowRays() const { return lightRays > 0 ? lightRays : gatherRays; }
  // gatherRays 0 with lightRays: the direct light per hit, the indirect light the solution's;
  bool indirectFromSolution() const { return gatherRays == 0 && lightRays > 0; }
  // whether rays are cast per hit at all (otherwise the solution is interpolated there).
  bool castsRays() const { return gatherRays > 0 || lightRays > 0; }
};

// The eye pass over a radiosity solution (B per element, stored on the mesh): L(D|S)*E from the
// camera, with the diffuse transport read from the solution. Mirrors and glass continue the ray,
// so they show the radiosity world, emitters included (past kSpecularRouletteAfter bounces by
// Russian roulette, with no cut-off).
class FinalGather : public Integrator {
 public:
  // `radiosity`: B per element (W/m²); emission E = π·Ke comes from the materials.
  FinalGather(const RenderScene& scene, const std::vector<Rgb>& radiosity,
              FinalGatherOptions options);

  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Rng& rng,
               RayCounts& counts) const override;
  // Shadow-ray points and gather directions come from `sampler` (stratified across the pixel).
  Rgb radiance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, Sampler& sampler,
               RayCounts& counts) const override;
  std::string name() const override;

  // Outgoing radiance at a point of a diffuse element (barycentrics over its corners), seen from
  // its front (for baking lightmaps by per-texel final gather): Ke + rho·(direct + gathered
  // light), rho the texel there. Mirrors and glass hold no radiance of their own here: 0.
  Rgb outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng,
                       RayCounts& counts) const;
  // The same value (bit for bit, from the same rng), and per channel the standard error of that
  // Monte Carlo estimate: ρ·√(Σ s²/n) over its means (the shadow rays', each area light's, the
  // gather rays'), s² the sample variance of the n samples of each. The samples are taken as
  // independent; their n-rooks stratification can only lower the true error below this (up to
  // a factor √(n/(n−1))). 0 where nothing is sampled (a delta light alone, ρ = 0).
  Rgb outgoingRadiance(int element, const Eigen::Vector3d& barycentric, Rng& rng, RayCounts& counts,
                       Rgb& standardError) const;
  // The same over a lightmap texel's footprint on the element: every shadow and gather ray (and
  // each delta light's share of them) leaves from its own point, stratified over the texel, so
  // the value is the texel's box-filtered mean, not its centre's (a shadow edge or the light's
  // fall-off inside the texel averaged as Cycles' bake averages them). ρ is the centre's, as
  // with one point. A footprint that is a point gives the value above, bit for bit.
  Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Rng& rng, RayCounts& counts,
                       Rgb& standardError) const;
  // The same with its points drawn from `sampler` (a texel's SobolSampler: its N rays of each
  // kind one stratified set); `standardError` still treats them as independent, so where the
  // stratification helps it overstates the error.
  Rgb outgoingRadiance(int element, const TexelFootprint& footprint, Sampler& sampler,
                       RayCounts& counts, Rgb& standardError) const;

 private:
  // gatherRays 0 with shadow rays: the direct light at each hit by its own shadow rays (a shadow's
  // edge, a light's fall-off, exact however coarse the mesh), the interreflected light from the
  // solution, interpolated: no gather ray, so no gather noise; the indirect part's discretisation
  // is the bias, small where the indirect light varies slowly (docs/rendering.md).
  bool indirectFromSolution() const { return options_.indirectFromSolution(); }
  Rgb interpolatedRadiance(const SurfaceHit& hit) const;  // B/π at the hit, from vertex values
  // The solution's indirect incident light H_i/π at barycentrics (u, v) of `element`, from
  // vertexIndirect_.
  Rgb interpolatedIndirect(int element, double u, double v) const;
  // Per element: the mean over its exposed points of the direct irradiance / π, from the
  // emitters and the scene lights; the latter's part alone (sun, sky, lamps).
  std::vector<Rgb> meanDirectLight() const;
  std::vector<Rgb> meanSceneLight() const;
  // indirectFromSolution: what a cosine-sampled ray from `from` finds of the lights straight
  // ahead (an emitter, the sky), MIS-weighted against one shadow ray per cosine ray.
  Rgb lightAlong(const SurfaceHit& from, const Eigen::Vector3d& direction, RayCounts& counts) const;
  // `variance`, when given, gains the variance of each estimate's mean (s²/n per channel).
  // `footprint`, when given, spreads the samples' origins over it (see outgoingRadiance).
  Rgb directLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                  Rgb* variance = nullptr,
                  const TexelFootprint* footprint = nullptr) const;  // ∫ L_e cos dω / π
  // The mean incoming radiance along cosine rays: the solution's reflected light (gather), or
  // under indirectFromSolution only the lights they meet (lightAlong), the shadow rays' MIS pair.
  Rgb gatherLight(const SurfaceHit& hit, Sampler& sampler, RayCounts& counts,
                  Rgb* variance = nullptr, const TexelFootprint* footprint = nullptr) const;
  // `count` positions on hit's element spread over `footprint` (n-rooks stratified) into `out`;
  // none, and nothing drawn from `sampler`, when there is no footprint or it is a point.
  void spreadOrigins(const SurfaceHit& hit, const TexelFootprint* footprint, Sampler& sampler,
                     int count, std::vector<Eigen::Vector3d>& out) const;
  // One shadow ray to the point `u` picks on the emitters: its irradiance / π, MIS-weighted
  // against a cosine-sampled ray.
  // `gathersPerLight`: cosine rays per shadow ray in the MIS pair (power heuristic with counts).
  Rgb lightSample(const SurfaceHit& hit, Point2 u, RayCounts& counts,
                  double gathersPerLight = 1.0) const;
  int lightRays() const { return options_.shadowRays(); }
  // Per element: the mean of lightSample over its area (stratified points), and whether every
  // one of those points saw the emitters alike (all lit, or none: no shadow edge, no emitter
  // plane crossing the element).
  struct ElementLight {
    std::vector<Rgb> mean;
    std::vector<char> uniform;
  };
  ElementLight meanLightSample() const;
  // Incoming radiance along a gather ray leaving `from`; `mayContinue`: a landing too close
  // gathers once more (the continuation itself reads the solution wherever it lands).
  Rgb secondaryRadiance(const SurfaceHit& from, Eigen::Vector3d direction, Rng& rng,
                        RayCounts& counts, bool mayContinue) const;
  static double misWeight(double pdfA, double pdfB);

  const RenderScene& scene_;
  FinalGatherOptions options_;
  std::vector<Rgb> radiance_;   // B/π per element
  std::vector<Rgb> reflected_;  // (B − E)/π per element
  std::vector<Rgb> emitted_;    // Le per element (its texture's average)
  std::vector<Rgb> rho_;        // reflectance per element (its texture's average), as solved
  // H/π interpolated to the vertices (gatherRays 0 with textures): the albedo-free light that
  // the texel's ρ multiplies, smooth across elements of different mean reflectance.
  std::vector<Eigen::Vector3d> vertexIncident_;
  // (B − E)/π − ρ·(the element's mean of lightSample) per element: the solution's reflected
  // light less its shadow-ray share, which a gather ray's landing point takes at the point.
  std::vector<Rgb> indirect_;
  // Per element: its points all saw the emitters alike, so a landing there takes the element's
  // mean shadow-ray share instead of casting its own shadow ray.
  std::vector<char> uniformLight_;
  std::vector<double> elementSize_;  // √area per element: a gather ray landing closer continues
  // The buried parts of the elements (element_exposure.h): the mean light of an element is over
  // its exposed points, and vertex values weigh elements by their exposed areas.
  ElementExposure exposure_;
  VertexInterpolation interpolation_;
  std::vector<Eigen::Vector3d> vertexRadiance_;  // B/π per output vertex (gather 0)
  // indirectFromSolution: per output vertex, the solution's reflected light less its direct
  // part, divided by ρ: the albedo-free indirect light H_i/π that the point's ρ multiplies.
  std::vector<Eigen::Vector3d> vertexIndirect_;
};

}  // namespace rad
