// Directional lightmaps (render/directional_lightmap.h): the L1 SH texels of a floor under a lone
// sun (exactly the sun's direction), with a wall that bounces light onto it (its closed-form
// vector irradiance added), and under a uniform sky (the hemisphere's projection, the
// reconstructed irradiance π L); the pages are the same whatever the thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <vector>

#include "meshing/lightmap_charts.h"
#include "meshing/lightmap_packing.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/errors.h"
#include "radiosity/render/directional_lightmap.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

constexpr double kY0 = 0.28209479177387814, kY1 = 0.4886025119029199;

// The floor [0, 2] × [0, 2] at y = 0 facing up (+y), element 0.. of the mesh.
std::vector<Eigen::Vector3d> floorCorners() { return {{0, 0, 0}, {0, 0, 2}, {2, 0, 2}, {2, 0, 0}}; }

// The floor, and (with `wall`) a wall at x = 2 over z in [0, 2], `wallHeight` high, facing −x.
PatchMesh floorMesh(bool wall, double wallHeight = 0.5) {
  std::vector<Eigen::Vector3d> p = floorCorners();
  std::vector<PatchPolygon> faces = {{{0, 1, 2, 3}, 0}};
  if (wall) {
    p.insert(p.end(), {{2, 0, 0}, {2, 0, 2}, {2, wallHeight, 2}, {2, wallHeight, 0}});
    faces.push_back({{4, 5, 6, 7}, 0});
  }
  PatchMesh mesh(p, faces);
  mesh.subdivideUniform(0.1);
  return mesh;
}

Scene sceneWith(const std::vector<Light>& lights) {
  Scene scene;
  scene.sourcePath = "test";
  Material grey;
  grey.name = "grey";
  grey.diffuse = {0.5, 0.5, 0.5};
  scene.materials.push_back(grey);
  scene.lights = lights;
  return scene;
}

// A meshed scene with its lightmap layout, ready to bake.
struct Baked {
  Scene scene;
  PatchMesh mesh;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
  LightmapLayout layout;
  std::unique_ptr<VertexInterpolation> interpolation;
  Baked(Scene s, PatchMesh m) : scene(std::move(s)), mesh(std::move(m)) {
    caster = std::make_unique<RayCaster>(mesh);
    view = std::make_unique<RenderScene>(scene, mesh, *caster);
    layout = packLightmapCharts(buildLightmapCharts(mesh), {0.125, 1024, 2});
    interpolation = std::make_unique<VertexInterpolation>(mesh);
  }
  DirectionalLightmapPage bake(const std::vector<Rgb>& radiosity, int rays, uint64_t seed = 1,
                               int page = 0) const {
    return bakeDirectionalPage(*view, radiosity, layout, *interpolation, 2, page, rays, seed);
  }
  // The point of texel i, as the bake took it: the texel centre's barycentric weights in its
  // element's lightmap triangle (a covered texel's centre lies inside it).
  Eigen::Vector3d texelPoint(const Lightmap& map, size_t i) const {
    const int e = map.element[i];
    const auto& t = layout.texels[e];
    const Eigen::Vector2d p(i % layout.width + 0.5, i / layout.width + 0.5);
    Eigen::Matrix2d m;
    m << t[1].x() - t[0].x(), t[2].x() - t[0].x(), t[1].y() - t[0].y(), t[2].y() - t[0].y();
    const Eigen::Vector2d w = m.inverse() * (p - Eigen::Vector2d(t[0].x(), t[0].y()));
    const auto c = mesh.corners(e);
    return (1 - w[0] - w[1]) * c[0] + w[0] * c[1] + w[1] * c[2];
  }
};

Light sun(const Eigen::Vector3d& travel, const Rgb& irradiance) {
  Light l;
  l.type = LightType::Directional;
  l.direction = travel.normalized();
  l.irradiance = irradiance;
  return l;
}

// The L1 vector (world x, y, z) of channel `ch` at texel i.
Eigen::Vector3d l1Vector(const DirectionalLightmapPage& p, size_t i, int ch) {
  return {p.coefficients[3].radiance.pixels[i][ch], p.coefficients[1].radiance.pixels[i][ch],
          p.coefficients[2].radiance.pixels[i][ch]};
}

double degreesBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

// ∫ ω dω over the solid angle of the planar polygon `corners` seen from x (Arvo's vector
// irradiance of a uniform unit-radiance polygon): ½ Σ_edges θ_i n_i, θ_i the angle the edge
// subtends and n_i the unit normal of the plane through x and the edge, oriented towards the
// polygon.
Eigen::Vector3d polygonVectorIrradiance(const std::vector<Eigen::Vector3d>& corners,
                                        const Eigen::Vector3d& x) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), centre = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d a = (corners[i] - x).normalized(),
                          b = (corners[(i + 1) % corners.size()] - x).normalized();
    sum += 0.5 * std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * a.cross(b).normalized();
    centre += corners[i];
  }
  centre = centre / corners.size() - x;
  return sum.dot(centre) >= 0 ? sum : Eigen::Vector3d(-sum);
}

// A sun alone over a floor: no ray meets anything, so the coefficients are the sun's analytic
// term c_k = E Y_k(towards the sun) at every covered texel, to rounding: the L1 vector points at
// the sun. Below the horizon (a sun under the floor) it adds nothing.
TEST(DirectionalLightmap, LoneSunGivesItsOwnDirectionExactly) {
  const Light s = sun({0.3, -1, 0.2}, {3, 2, 1});
  Baked b(sceneWith({s}), floorMesh(false));
  const std::vector<Rgb> radiosity(b.mesh.elementCount(), Rgb{0.4, 0.3, 0.2});
  const DirectionalLightmapPage page = b.bake(radiosity, 16);
  const Eigen::Vector3d toSun = -s.direction;
  const std::array<double, 9> y = shBasis(toSun);
  size_t covered = 0;
  for (size_t i = 0; i < page.coefficients[0].state.size(); ++i) {
    if (page.coefficients[0].state[i] != TexelState::Covered) continue;
    ++covered;
    for (int ch = 0; ch < 3; ++ch) {
      for (int k = 0; k < 4; ++k)
        ASSERT_NEAR(page.coefficients[k].radiance.pixels[i][ch], s.irradiance[ch] * y[k], 1e-12)
            << "texel " << i << " k " << k;
      ASSERT_LT(degreesBetween(l1Vector(page, i, ch), toSun), 1e-6);
    }
    // The preview: 0.5 + 0.5 d, to 8 bits once encoded (linear here, its sRGB decoding).
    const Eigen::Vector3d d = toSun.normalized();
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(page.direction.pixels[i][a], srgbToLinear(0.5 + 0.5 * d[a]), 1e-9);
  }
  EXPECT_GT(covered, 200u);  // 16 × 16 texels on the floor, less its borders

  Baked under(sceneWith({sun({0.3, 1, 0.2}, {3, 2, 1})}), floorMesh(false));
  const DirectionalLightmapPage dark = under.bake(radiosity, 16);
  for (int k = 0; k < 4; ++k)
    for (const Rgb& p : dark.coefficients[k].radiance.pixels) ASSERT_TRUE(p.isZero());
  // Nothing in the way of that sun (a point far off the floor, facing up; as the back of a
  // two-sided surface lets it through): still below the horizon, so still nothing.
  Rng rng(1);
  const ProbeLights lights(under.scene);
  for (const Rgb& c : hemisphereL1(*under.view, radiosity, lights, {10, 5, 10}, {0, 1, 0}, 16, rng))
    EXPECT_TRUE(c.isZero());
  // Facing down there, it is the whole sun.
  const auto facing =
      hemisphereL1(*under.view, radiosity, lights, {10, 5, 10}, {0, -1, 0}, 16, rng);
  EXPECT_NEAR(facing[0].r, 3 * kY0, 1e-12);
}

// The sun, and a wall beside the floor lit by it (B = ρ E cos, its own first bounce; the floor's B
// does not reach the floor): every texel's L1 vector is the sun's term plus the wall's
// L_wall Y1 projection, L_wall ∫ Y1 dω = L_wall Y1-constant × (vector irradiance of the wall),
// within the estimator's spread; and still within 5° of the sun, tilted towards the wall.
TEST(DirectionalLightmap, BouncedLightFromAWallStaysNearTheSun) {
  const Light s = sun({0.3, -1, 0.2}, {3, 2, 1});
  Baked b(sceneWith({s}), floorMesh(true));
  const Eigen::Vector3d toSun = -s.direction;
  const Eigen::Vector3d wallNormal(-1, 0, 0);
  ASSERT_GT(wallNormal.dot(toSun), 0.2);  // the wall is lit
  std::vector<Rgb> radiosity(b.mesh.elementCount());
  std::vector<char> isWall(b.mesh.elementCount(), 0);
  for (int e = 0; e < b.mesh.elementCount(); ++e) {
    isWall[e] = b.mesh.normal(e).dot(wallNormal) > 0.99;
    const Eigen::Vector3d n = b.mesh.normal(e);
    radiosity[e] = s.irradiance * (0.5 * std::max(0.0, n.dot(toSun)));
  }
  const std::vector<Eigen::Vector3d> wall = {{2, 0, 0}, {2, 0, 2}, {2, 0.5, 2}, {2, 0.5, 0}};
  const int rays = 4096;
  const DirectionalLightmapPage page = b.bake(radiosity, rays, 9);
  const std::array<double, 9> ySun = shBasis(toSun);
  double largest = 0, largestTilt = 0;
  size_t checked = 0;
  for (size_t i = 0; i < page.coefficients[0].state.size(); ++i) {
    const int e = page.coefficients[0].element[i];
    if (page.coefficients[0].state[i] != TexelState::Covered || isWall[e]) continue;
    ++checked;
    const Eigen::Vector3d x = b.texelPoint(page.coefficients[0], i);
    const Eigen::Vector3d phi = polygonVectorIrradiance(wall, x);
    for (int ch = 0; ch < 3; ++ch) {
      const double lWall = s.irradiance[ch] * 0.5 * wallNormal.dot(toSun) / M_PI;
      const Eigen::Vector3d expected =
          s.irradiance[ch] * Eigen::Vector3d(ySun[3], ySun[1], ySun[2]) + lWall * kY1 * phi;
      const Eigen::Vector3d got = l1Vector(page, i, ch);
      // 4σ of a plain Monte Carlo estimate of the vector (each ray adds at most 2π Y1-constant
      // L_wall / N; stratification only lowers the spread).
      const double tolerance = 4 * 2 * M_PI * kY1 * lWall / std::sqrt(rays);
      ASSERT_NEAR((got - expected).norm(), 0, tolerance) << "texel " << i << " channel " << ch;
      const double angle = degreesBetween(got, toSun);
      EXPECT_LT(angle, 5.0) << "texel " << i;
      largest = std::max(largest, angle);
      // Tilted from the sun towards the wall (+x).
      largestTilt = std::max(largestTilt, got.normalized().x() - toSun.normalized().x());
    }
  }
  EXPECT_GT(checked, 200u);
  EXPECT_GT(largest, 0.5);  // the bounce is there
  EXPECT_GT(largestTilt, 0.0);
}

// A uniform sky of radiance L over a lone floor: every hemisphere ray sees L, so c0 = 2π L Y0 for
// any direction set. c_y = L π Y1-constant (∫ y dω over the hemisphere = π): the N directions
// hold one cos θ = y in each of N equal bands, so their mean y is within 1/(2N) of ½ and c_y
// within π L Y1-constant / N of its value, whatever the random shifts. c_x = c_z = 0 within 4σ
// of a plain Monte Carlo estimate with N rays (E x² = 1/3; the stratification only lowers it).
// The reconstructed irradiance facing up, π c0 Y0 + (2π/3) c_y Y1(up), is π L.
TEST(DirectionalLightmap, UniformSkyOverAFloorIsTheHemisphereProjection) {
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = {1, 2, 3};
  Baked b(sceneWith({sky}), floorMesh(false));
  const std::vector<Rgb> radiosity(b.mesh.elementCount(), Rgb{5, 5, 5});
  const int rays = 64;
  const DirectionalLightmapPage page = b.bake(radiosity, rays, 4);
  size_t covered = 0;
  for (size_t i = 0; i < page.coefficients[0].state.size(); ++i) {
    if (page.coefficients[0].state[i] != TexelState::Covered) continue;
    ++covered;
    for (int ch = 0; ch < 3; ++ch) {
      const double l = sky.radiance[ch];
      const double scale = 2 * M_PI * kY1 * l / std::sqrt(rays);
      const double c0 = page.coefficients[0].radiance.pixels[i][ch],
                   cy = page.coefficients[1].radiance.pixels[i][ch],
                   cz = page.coefficients[2].radiance.pixels[i][ch],
                   cx = page.coefficients[3].radiance.pixels[i][ch];
      ASSERT_NEAR(c0, 2 * M_PI * l * kY0, 1e-9 * l);
      const double bandBound = M_PI * l * kY1 / rays + 1e-12;
      ASSERT_NEAR(cy, M_PI * l * kY1, bandBound);
      ASSERT_NEAR(cx, 0, 4 * scale * std::sqrt(1 / 3.0));
      ASSERT_NEAR(cz, 0, 4 * scale * std::sqrt(1 / 3.0));
      const double irradiance = M_PI * c0 * kY0 + 2 * M_PI / 3 * cy * kY1;
      ASSERT_NEAR(irradiance, M_PI * l, 2 * M_PI / 3 * kY1 * bandBound);
    }
  }
  EXPECT_GT(covered, 200u);
}

// The texel's stream depends on the seed, the page and the texel only: one thread and many give
// the same page; another seed another.
TEST(DirectionalLightmap, SameForASeedWhateverTheThreadCount) {
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = {1, 1, 1};
  Baked b(sceneWith({sky, sun({0.3, -1, 0.2}, {1, 1, 1})}), floorMesh(true));
  std::vector<Rgb> radiosity(b.mesh.elementCount(), Rgb{0.3, 0.3, 0.3});
  DirectionalLightmapPage one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = b.bake(radiosity, 16, 3);
  }
  const DirectionalLightmapPage many = b.bake(radiosity, 16, 3);
  const DirectionalLightmapPage other = b.bake(radiosity, 16, 4);
  auto same = [](const Rgb& a, const Rgb& c) { return a.r == c.r && a.g == c.g && a.b == c.b; };
  bool differs = false;
  for (int k = 0; k < 4; ++k)
    for (size_t i = 0; i < one.coefficients[k].radiance.pixels.size(); ++i) {
      ASSERT_TRUE(
          same(one.coefficients[k].radiance.pixels[i], many.coefficients[k].radiance.pixels[i]))
          << "k " << k << " texel " << i;
      differs |=
          !same(one.coefficients[k].radiance.pixels[i], other.coefficients[k].radiance.pixels[i]);
    }
  EXPECT_TRUE(differs);
  EXPECT_THROW(b.bake(radiosity, 0), InputError);
}

}  // namespace
}  // namespace rad
