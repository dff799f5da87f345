#pragma once

#include <vector>

#include "meshing/vertex_interpolation.h"
#include "radiosity/render/integrator.h"

namespace rad {

struct FinalGatherOptions {
  // 0: show the interpolated radiosity B/π at the first diffuse hit (preview). N > 0: direct
  // light by N shadow rays to the emitters plus N cosine-weighted gather rays into the
  // solution's reflected part (B − E)/π; the two share the direct light by multiple importance
  // sampling (a gather ray that reaches an emitter adds its MIS-weighted Ke).
  int gatherRays = 64;
  int maxSpecularDepth = 16;  // mirror/glass bounces an eye or gather ray may take
};

// The eye pass over a radiosity solution (B per element, stored on the mesh): L(D|S)*E from the
// camera, with the diffuse transport read from the solution. Mirrors and glass continue the ray,
// so they show the radiosity world, emitters included.
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

  // Outgoing radiance at a point of a diffuse element, seen from its front (for baking
  // lightmaps by per-texel final gather): Ke + rho·(direct + gathered light). Mirrors and glass
  // hold no radiance of their own here: 0.
  Rgb outgoingRadiance(int element, const Eigen::Vector3d& position, Rng& rng, RayCounts& counts) const;

 private:
  Rgb interpolatedRadiance(const SurfaceHit& hit) const;  // B/π at the hit, from vertex values
  Rgb directLight(const SurfaceHit& hit, Sampler& sampler,
                  RayCounts& counts) const;  // ∫ L_e cos dω / π
  Rgb gatherLight(const SurfaceHit& hit, Sampler& sampler,
                  RayCounts& counts) const;  // mean incoming reflected L
  // Incoming radiance along a gather ray leaving `from`.
  Rgb secondaryRadiance(const SurfaceHit& from, Eigen::Vector3d direction, Rng& rng,
                        RayCounts& counts) const;
  static double misWeight(double pdfA, double pdfB);

  const RenderScene& scene_;
  FinalGatherOptions options_;
  std::vector<Rgb> radiance_;   // B/π per element
  std::vector<Rgb> reflected_;  // (B − E)/π per element
  VertexInterpolation interpolation_;
  std::vector<Eigen::Vector3d> vertexRadiance_;  // B/π per output vertex (gather 0)
};

}  // namespace rad
