#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/render/render_scene.h"

namespace rad {

// Light probes from a radiosity solution: at each point, the incident radiance L(ω)
// (W·m⁻²·sr⁻¹) projected onto the 9 real spherical harmonics of order ≤ 2, per RGB channel.
//
// Convention: the standard real SH as written in Sloan's "Stupid Spherical Harmonics (SH)
// Tricks" (the normalisation of Ramamoorthi & Hanrahan 2001), with (x, y, z) the unit
// direction's components in the scene's own frame (the scene is +y up, so Y1,-1 ∝ y is the
// up axis). Index k = l(l+1) + m:
//   k=0 Y0,0  = 0.282095                      k=4 Y2,-2 = 1.092548 xy
//   k=1 Y1,-1 = 0.488603 y                    k=5 Y2,-1 = 1.092548 yz
//   k=2 Y1,0  = 0.488603 z                    k=6 Y2,0  = 0.315392 (3z² − 1)
//   k=3 Y1,1  = 0.488603 x                    k=7 Y2,1  = 1.092548 xz
//                                             k=8 Y2,2  = 0.546274 (x² − y²)
// Orthonormal over the sphere: ∫ Y_i Y_j dω = δ_ij.
std::array<double, 9> shBasis(const Eigen::Vector3d& direction);

struct ProbeSh {
  Eigen::Vector3d position{0, 0, 0};
  std::array<Rgb, 9> coefficients{};  // c_k = ∫ L(ω) Y_k(ω) dω (W·m⁻²)
  bool inside = false;                // more than half the rays hit back faces: inside geometry
};

// The coefficients at each of `points`: `rays` directions from a spherical Fibonacci set, rotated
// per probe by a random rotation seeded from (seed, probe index), each weighted 4π/rays. A ray
// that hits a surface sees the hit element's B/π on its front face (0 from its back, counted as a
// back-face hit); one that leaves the scene sees the sky and environment lights (skyRadiance). The
// point, spot and directional lights (a sun with an angular diameter over its disc, as everywhere
// else, and so not also seen by the escaped rays: lightArrivals) are added when their shadow
// ray is clear: c_k += E · Y_k(ω_l), E the irradiance on a surface facing the light and ω_l the
// direction towards it. `radiosity`: B per element of view.mesh(). Deterministic for a seed,
// whatever the thread count.
std::vector<ProbeSh> computeProbes(const RenderScene& view, const std::vector<Rgb>& radiosity,
                                   const std::vector<Eigen::Vector3d>& points, int rays,
                                   uint64_t seed);

// The scene's lights as a probe ray sees them: at infinity, seen by the rays that leave the scene
// (sky, environment), and the delta lights and suns' discs added by their samples. Shared
// with the directional lightmaps (render/directional_lightmap.h).
struct ProbeLights {
  std::vector<const Light*> skies, deltas, discs;  // discs: suns with an angular diameter
  explicit ProbeLights(const Scene& scene);
};

// What one probe ray from `origin` (already lifted off any surface) along the unit `direction`
// sees, W·m⁻²·sr⁻¹: the hit element's B/π on its front face, 0 on a back face (then *backFace is
// set, when given), the skies' radiance (skyRadiance) when it leaves the scene.
Rgb probeRayRadiance(const RenderScene& view, const std::vector<Rgb>& radiosity,
                     const ProbeLights& lights, const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& direction, bool* backFace = nullptr);

// Light from one direction at a point: the unit direction towards it and the irradiance (W·m⁻²)
// on a surface facing it.
struct LightArrival {
  Eigen::Vector3d toLight;
  Rgb irradiance;
};
// The lights of `lights` not seen by escaped rays, whose shadow ray from `point` (already lifted
// off any surface) is clear, through the lighting layer's samples (lighting/light_sample.h): each
// delta light by E⊥ (a point or spot light intensity × falloff / r², a hard sun its irradiance),
// a sun's disc as the centres of 4 × 4 equal strata of it, each with its share of the irradiance
// (so a probe in its penumbra sees the part of the disc it sees, as the solve and the renders do).
std::vector<LightArrival> lightArrivals(const RenderScene& view, const ProbeLights& lights,
                                        const Eigen::Vector3d& point);

// Irradiance (W/m²) on a surface of unit normal `normal` at the probe, from the coefficients
// (Ramamoorthi & Hanrahan 2001): E(n) = Σ_k Â_l c_k Y_k(n), Â_0 = π, Â_1 = 2π/3, Â_2 = π/4.
Rgb probeIrradiance(const ProbeSh& probe, const Eigen::Vector3d& normal);

// A grid over the box [lo, hi] with `spacing`: floor((hi − lo)/spacing) + 1 points on each axis,
// centred in the box, x fastest then y then z. InputError when spacing is not a positive finite
// number, the box is empty or not finite, or the grid would exceed 1,000,000 points.
std::vector<Eigen::Vector3d> probeGrid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                       double spacing);

// probes.json: {"convention": "...", "unit": "...", "probes": [{"position": [x, y, z],
// "inside": false, "sh": [[r, g, b] × 9]}]}, "sh" in index order k = 0..8.
void writeProbesJson(std::ostream& out, const std::vector<ProbeSh>& probes);

// probes.bin, little-endian: 8 bytes "RADPRB01", u32 probe count, then per probe 3 f32 position,
// 27 f32 coefficients k-major (c0.r c0.g c0.b c1.r ... c8.b), u32 flags (bit 0: inside): 124
// bytes a probe after the 12-byte header.
void writeProbesBinary(std::ostream& out, const std::vector<ProbeSh>& probes);

// The most probes a probes.bin may hold: probeGrid's limit.
inline constexpr uint32_t kMaxProbes = 1000000;

// Reads a probes.bin (the layout above) whole, or nothing: InputError naming `path` when it cannot
// be opened, does not start with "RADPRB01", is shorter or longer than its count says (12 + 124 ×
// count bytes), counts more than kMaxProbes, or holds a position or coefficient that is not
// finite, or flags other than bit 0. The file's length is checked against the count before any
// allocation.
std::vector<ProbeSh> readProbesBinary(const std::string& path);

}  // namespace rad
