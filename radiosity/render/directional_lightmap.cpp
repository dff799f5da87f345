// Directional lightmaps: order-1 SH of the incident radiance over each texel's hemisphere.
#include "radiosity/render/directional_lightmap.h"

#include <atomic>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/scene/texture.h"

namespace rad {
namespace {

constexpr double kGoldenTurn = 0.6180339887498949;  // 1 / golden ratio
constexpr uint64_t kTexelStream = stream_tag::kDirectionalTexel;

// Two unit vectors completing `n` to a right-handed orthonormal frame (Duff et al. 2017).
void tangentFrame(const Eigen::Vector3d& n, Eigen::Vector3d& t, Eigen::Vector3d& b) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1 / (sign + n.z()), c = n.x() * n.y() * a;
  t = Eigen::Vector3d(1 + sign * n.x() * n.x() * a, sign * c, -sign * n.x());
  b = Eigen::Vector3d(c, sign + n.y() * n.y() * a, -n.y());
}

}  // namespace

const char* const kDirectionalConvention =
    "order-1 real spherical harmonics of the incident radiance over the texel's hemisphere (0 "
    "below it), Sloan 'Stupid SH Tricks' normalisation, (x, y, z) the direction in the scene frame "
    "(+y up): L0 = c0 (Y00 = 0.282095), L1x = c3 (Y11 = 0.488603 x), L1y = c1 (Y1-1 = 0.488603 y), "
    "L1z = c2 (Y10 = 0.488603 z); c_k = integral of L(w) Y_k(w) dw; irradiance for a unit normal "
    "n: "
    "E(n) = pi c0 Y00 + (2pi/3) (L1x Y11(n) + L1y Y1-1(n) + L1z Y10(n))";

std::string directionalFileName(int page, int pages, const std::string& what) {
  return pages == 1 ? "lightmap_" + what : "lightmap_" + std::to_string(page) + "_" + what;
}

const std::array<const char*, 4>& directionalCoefficientNames() {
  static const std::array<const char*, 4> names = {"sh_L0", "sh_L1y", "sh_L1z", "sh_L1x"};
  return names;
}

std::array<Rgb, 4> hemisphereL1(const RenderScene& view, const std::vector<Rgb>& radiosity,
                                const ProbeLights& lights, const Eigen::Vector3d& point,
                                const Eigen::Vector3d& normal, int rays, Rng& rng) {
  std::array<Rgb, 4> c{};
  const Eigen::Vector3d n = normal.normalized();
  const Eigen::Vector3d origin = view.caster().liftOff(point, n, n);
  Eigen::Vector3d t, b;
  tangentFrame(n, t, b);
  const double bandShift = rng.uniform(), turnShift = rng.uniform();
  const double weight = 2 * M_PI / rays;
  for (int i = 0; i < rays; ++i) {
    const double cosTheta = (i + bandShift) / rays;  // band i of cos θ: uniform in solid angle
    const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    const double turn = i * kGoldenTurn + turnShift;
    const double phi = 2 * M_PI * (turn - std::floor(turn));
    const Eigen::Vector3d d =
        (sinTheta * (std::cos(phi) * t + std::sin(phi) * b) + cosTheta * n).normalized();
    const Rgb radiance = probeRayRadiance(view, radiosity, lights, origin, d);
    if (radiance.isZero()) continue;
    const std::array<double, 9> y = shBasis(d);
    for (int k = 0; k < 4; ++k) c[k] += radiance * (weight * y[k]);
  }
  for (const LightArrival& a : lightArrivals(view, lights, origin)) {
    if (!(a.toLight.dot(n) > 0)) continue;  // below the texel's horizon
    const std::array<double, 9> y = shBasis(a.toLight);
    for (int k = 0; k < 4; ++k) c[k] += a.irradiance * y[k];
  }
  return c;
}

DirectionalLightmapPage bakeDirectionalPage(const RenderScene& view,
                                            const std::vector<Rgb>& radiosity,
                                            const LightmapLayout& layout,
                                            const VertexInterpolation& interpolation,
                                            int dilationRadius, int page, int rays, uint64_t seed) {
  if (rays < 1) throw InputError("--directional-rays must be at least 1");
  const PatchMesh& mesh = view.mesh();
  RAD_CHECK_EQ(radiosity.size(), static_cast<size_t>(mesh.elementCount()));
  const ProbeLights lights(view.scene());
  const size_t texels = static_cast<size_t>(layout.width) * layout.height;
  // The four coefficients of each texel, cast once (by the first bake) and read on its texels.
  std::vector<std::array<Rgb, 4>> table(texels);
  std::vector<char> cast(texels, 0);
  const std::vector<Rgb> unused(interpolation.vertexCount());  // every owned texel is evaluated
  DirectionalLightmapPage out;
  out.coefficients[0] = bakeLightmap(
      mesh, layout, interpolation, unused, dilationRadius,
      [&](int e, const Eigen::Vector3d& bary, size_t texel) {
        const auto p = mesh.corners(e);
        const Eigen::Vector3d x = bary[0] * p[0] + bary[1] * p[1] + bary[2] * p[2];
        Rng rng(streamKey(seed, kTexelStream + static_cast<uint64_t>(page), texel));
        table[texel] = hemisphereL1(view, radiosity, lights, x, mesh.normal(e), rays, rng);
        cast[texel] = 1;
        return table[texel][0];
      },
      page);
  for (int k = 1; k < 4; ++k)
    out.coefficients[k] = bakeOnTexels(
        out.coefficients[0], layout, [&, k](int, const Eigen::Vector3d&, size_t texel) {
          RAD_CHECK_MSG(cast[texel], "directional lightmap: a texel the first bake did not own");
          return table[texel][k];
        });
  out.direction = ImageRgb(layout.width, layout.height);
  const Lightmap& l0 = out.coefficients[0];
  for (size_t i = 0; i < texels; ++i) {
    if (l0.state[i] == TexelState::Empty) continue;
    const Eigen::Vector3d v(out.coefficients[3].radiance.pixels[i].luminance(),
                            out.coefficients[1].radiance.pixels[i].luminance(),
                            out.coefficients[2].radiance.pixels[i].luminance());
    const double length = v.norm();
    const Eigen::Vector3d d =
        length > 0 && std::isfinite(length) ? Eigen::Vector3d(v / length) : Eigen::Vector3d::Zero();
    Rgb& pixel = out.direction.pixels[i];
    for (int a = 0; a < 3; ++a) pixel[a] = srgbToLinear(0.5 + 0.5 * d[a]);
  }
  return out;
}

}  // namespace rad
