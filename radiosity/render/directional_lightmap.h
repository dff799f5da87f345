#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/image.h"
#include "radiosity/core/rgb.h"
#include "radiosity/core/rng.h"
#include "radiosity/output/lightmap_bake.h"
#include "radiosity/render/light_probes.h"
#include "radiosity/render/render_scene.h"

namespace rad {

// Directional lightmaps (`bake --directional`): per texel, the order-1 spherical-harmonic
// projection of the incident radiance over the hemisphere above the texel's point on its
// element's front side (below it: 0), c_k = ∫ L(ω) Y_k(ω) dω for k = 0..3, in W·m⁻² per RGB
// channel. The basis is shBasis (render/light_probes.h): Sloan's real SH in the scene's own frame
// (+y up), Y0,0 = 0.282095, Y1,-1 = 0.488603 y, Y1,0 = 0.488603 z, Y1,1 = 0.488603 x. An engine
// evaluates the irradiance on a surface of (normal-mapped) unit normal n as
//   E(n) = π c0 Y0,0 + (2π/3) Σ_m c1m Y1m(n),
// and the L1 vector (c3, c1, c2) (world x, y, z) points towards where the light comes from.
//
// What a ray sees is what the light probes see (probeRayRadiance: B/π of the hit element on its
// front face, 0 on a back face, the sky and environment when it leaves); the point, spot and
// directional lights above the texel's horizon are added analytically behind a shadow ray,
// c_k += E · Y_k(ω_l) (lightArrivals).

// The texel's lightmap files, for page `page` of `pages`: "lightmap_" + what for one page,
// "lightmap_<page>_" + what for several (what: e.g. "sh_L0.exr", "direction.png").
std::string directionalFileName(int page, int pages, const std::string& what);

// The four coefficient files' names, k = 0..3 in shBasis order: "sh_L0", "sh_L1y", "sh_L1z",
// "sh_L1x" (L1x holds c3 ∝ x, L1y c1 ∝ y, L1z c2 ∝ z).
const std::array<const char*, 4>& directionalCoefficientNames();

// The convention, as bake.json states it.
extern const char* const kDirectionalConvention;

// The coefficients k = 0..3 at `point` of the element of unit front normal `normal`: `rays`
// directions stratified over the hemisphere, uniform in solid angle, each weighted 2π/rays — one
// in each of `rays` equal bands of cos θ, the azimuths a golden-ratio sequence (a spherical
// Fibonacci set), both shifted by two uniforms drawn from `rng` (so unbiased). Then the delta
// lights above the horizon.
std::array<Rgb, 4> hemisphereL1(const RenderScene& view, const std::vector<Rgb>& radiosity,
                                const ProbeLights& lights, const Eigen::Vector3d& point,
                                const Eigen::Vector3d& normal, int rays, Rng& rng);

struct DirectionalLightmapPage {
  // Per coefficient k = 0..3 (shBasis order), the page rasterised and dilated as the main
  // lightmap is (bakeLightmap); the rays are cast once per texel.
  std::array<Lightmap, 4> coefficients;
  // The L1 vector of luminance (c3, c1, c2 each by Rec. 709 luminance), normalised, d ↦ 0.5 +
  // 0.5 d, stored linear so that encodePng at exposure 1 writes those values as its sRGB bytes;
  // black where the page is empty, 0.5 grey where the vector is 0.
  ImageRgb direction;
};

// One page of directional lightmaps from `radiosity` (B per element of view.mesh()), `rays` per
// texel. The texel's random stream is streamKey(seed, stream_tag::kDirectionalTexel + page, texel),
// so the page is the same for a seed whatever the thread count. InputError when rays < 1.
DirectionalLightmapPage bakeDirectionalPage(const RenderScene& view,
                                            const std::vector<Rgb>& radiosity,
                                            const LightmapLayout& layout,
                                            const VertexInterpolation& interpolation,
                                            int dilationRadius, int page, int rays, uint64_t seed);

}  // namespace rad
