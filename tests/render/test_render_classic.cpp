// The classic methods against analytic answers: the local model's point-light irradiance, the
// shadow rays that tell Whitted's tracer from it, the soft shadow of distribution ray tracing
// (Lambert's point-to-polygon form factor), its depth of field (a plane in focus stays sharp),
// its motion blur (coverage over the shutter) and the normalisation of the glossy lobe.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "radiosity/render/camera.h"
#include "radiosity/render/direct_lighting.h"
#include "radiosity/render/distribution_ray_tracer.h"
#include "radiosity/render/glossy_lobe.h"
#include "radiosity/render/image_renderer.h"
#include "radiosity/render/whitted_ray_tracer.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"

namespace rad {
namespace {

const std::string kData = std::string(RADIOSITY_DATA_DIR) + "/tests/";

// A scene loaded and meshed without a solve (the classic methods need none), optionally with
// the motion of a camera file.
struct LoadedScene {
  Scene scene;
  std::unique_ptr<PatchMesh> mesh;
  std::unique_ptr<SceneMotion> motion;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
  explicit LoadedScene(const std::string& obj, const std::string& motionFile = "") {
    scene = loadObjScene(obj);
    mesh = std::make_unique<PatchMesh>(buildPatchMesh(scene));
    if (!motionFile.empty())
      motion = std::make_unique<SceneMotion>(scene, *mesh, loadMotionSpec(motionFile));
    caster = std::make_unique<RayCaster>(*mesh, motion ? &motion->vertices() : nullptr);
    view = std::make_unique<RenderScene>(scene, *mesh, *caster, motion.get());
  }
};

// Mean and standard error of `n` independent estimates of `f(rng)` (one channel).
template <class F>
std::pair<double, double> meanAndError(int n, uint64_t key, F f) {
  Rng rng(key);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double v = f(rng);
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

// Lambert's point-to-polygon form factor (REFERENCES.md), magnitude.
double pointToPolygon(const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                      const std::vector<Eigen::Vector3d>& polygon) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d a = polygon[i] - p, b = polygon[(i + 1) % polygon.size()] - p;
    const double beta = std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
    sum += beta * n.dot(a.cross(b).normalized());
  }
  return std::abs(sum) / (2 * M_PI);
}

// The tiny light (Le·A = 1 W/sr/... straight down, 1 above the origin): at floor point (a, 0, b)
// with r² = 1 + a² + b², cosθ_light = cosθ_surface = 1/r, so E = 1/r⁴ and L = Kd/π · E.
TEST(DirectMethod, EqualsTheAnalyticPointLightIrradianceOnAPlane) {
  LoadedScene s(kData + "point_light_plane.obj");
  const DirectLighting direct(*s.view);
  const WhittedRayTracer whitted(*s.view);
  const Rgb kd(0.5, 0.4, 0.3);
  int checked = 0;
  for (double a = -3; a <= 3; a += 0.75)
    for (double b = -2; b <= 2; b += 0.5) {
      const Eigen::Vector3d target(a, 0, b), origin(a + 0.2, 0.5, b - 0.1);
      const Eigen::Vector3d d = (target - origin).normalized();
      Rng rng(1);
      RayCounts counts;
      const Rgb got = direct.radiance(origin, d, rng, counts);
      const Rgb traced = whitted.radiance(origin, d, rng, counts);
      const double r2 = 1 + a * a + b * b;
      const Rgb expected = kd * (1.0 / (M_PI * r2 * r2));
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[c], expected[c], 1e-5 * expected[c]) << a << ", " << b;
        // Nothing blocks the light: Whitted's shadow rays all pass, and it agrees.
        EXPECT_NEAR(traced[c], expected[c], 1e-5 * expected[c]) << a << ", " << b;
      }
      ++checked;
    }
  EXPECT_GT(checked, 50);
}

// The image renderer's pixel means, for a camera looking straight down: each pixel lies between
// the analytic radiance at the extremes of its footprint on the floor.
TEST(DirectMethod, RenderedPixelsLieBetweenTheAnalyticValuesAtTheirCorners) {
  LoadedScene s(kData + "point_light_plane.obj");
  const DirectLighting direct(*s.view);
  Camera camera;
  camera.position = {0.3, 0.8, 0.2};
  camera.lookAt = {0.3, 0, 0.2};
  camera.up = {0, 0, 1};
  camera.vfovDegrees = 60;
  camera.width = camera.height = 12;
  RenderSettings settings;
  settings.samplesPerPixel = 4;
  settings.showProgress = false;
  const RenderOutput out = renderImage(camera, direct, settings);
  const CameraRays rays(camera);
  auto analytic = [](const Eigen::Vector3d& p) {
    const double r2 = 1 + p.x() * p.x() + p.z() * p.z();
    return 0.5 / (M_PI * r2 * r2);
  };
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      // The footprint is an axis-aligned rectangle on the floor (the camera looks straight
      // down with up +z); the radiance falls with the distance from the point under the light,
      // so its extremes are at the footprint's nearest point to the origin and farthest corner.
      double xmin = 1e30, xmax = -1e30, zmin = 1e30, zmax = -1e30, lo = 1e30;
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector3d o, d;
        rays.generate(x + (k & 1), y + (k >> 1), 0, 0, o, d);
        const Eigen::Vector3d p = o + d * (-o.y() / d.y());
        xmin = std::min(xmin, p.x());
        xmax = std::max(xmax, p.x());
        zmin = std::min(zmin, p.z());
        zmax = std::max(zmax, p.z());
        lo = std::min(lo, analytic(p));
      }
      const double hi = analytic({std::clamp(0.0, xmin, xmax), 0, std::clamp(0.0, zmin, zmax)});
      EXPECT_GE(out.image.at(x, y).r, lo * (1 - 1e-6)) << x << ", " << y;
      EXPECT_LE(out.image.at(x, y).r, hi * (1 + 1e-6)) << x << ", " << y;
    }
}

// Under the panel of soft_shadow.obj the light's centre is hidden from (-1, 0, 0): the local
// model has no visibility and still lights the point (E = Le·A·cos²/r² with r² = 2), Whitted's
// shadow ray to the centre is blocked.
TEST(DirectMethod, IgnoresOccludersWhereWhittedCastsAShadow) {
  LoadedScene s(kData + "soft_shadow.obj");
  const Eigen::Vector3d origin(-1, 0.1, 0), down(0, -1, 0);
  Rng rng(1);
  RayCounts counts;
  const Rgb direct = DirectLighting(*s.view).radiance(origin, down, rng, counts);
  const Rgb whitted = WhittedRayTracer(*s.view).radiance(origin, down, rng, counts);
  const double expected = 0.5 / M_PI * 2.0 * 1.0 * 0.5 / 2.0;
  EXPECT_NEAR(direct.r, expected, 1e-6 * expected);
  EXPECT_EQ(whitted.r, 0.0);
}

// Distribution ray tracing's soft shadow converges to ρ·Le·F, F the form factor from the floor
// point to the part of the light the panel leaves visible: the umbra, the penumbra and full
// light, within 4σ of the estimate.
TEST(DistributionMethod, SoftShadowConvergesToThePointToPolygonFormFactor) {
  LoadedScene s(kData + "soft_shadow.obj");
  const DistributionRayTracer tracer(*s.view);
  const double rho = 0.5, le = 2;
  for (double p : {-0.8, -0.35, 0.0, 0.25, 0.8}) {
    const double z = 0.1;
    const double x0 = std::max(-0.5, -p);
    double expected = 0;
    if (x0 < 0.5)
      expected = rho * le *
                 pointToPolygon({p, 0, z}, {0, 1, 0},
                                {{x0, 1, -0.5}, {0.5, 1, -0.5}, {0.5, 1, 0.5}, {x0, 1, 0.5}});
    const auto [mean, error] =
        meanAndError(4000, 7 + static_cast<uint64_t>(10 * (p + 1)), [&](Rng& rng) {
          RayCounts counts;
          return tracer.radiance({p, 0.1, z}, {0, -1, 0}, rng, counts).r;
        });
    EXPECT_NEAR(mean, expected, 4 * error + 1e-12) << "floor point x = " << p;
    if (p > 0.6) {
      EXPECT_GT(mean, 0.1);  // fully lit: not trivially dark
    }
  }
}

// Depth of field: looking along +z at the black square (z = 0.5) in front of the emitting
// backdrop (Le 1) of motion_blur.obj through a lens. Focused on the square, every ray of a pixel
// meets the pinhole ray at the square's plane: a pixel whose footprint there lies inside the
// square is exactly 0, outside exactly 1. Focused on the backdrop, the square's edge blurs.
TEST(DistributionMethod, APlaneInFocusStaysSharp) {
  LoadedScene s(kData + "motion_blur.obj");  // no motion file: the square stands still
  const DistributionRayTracer tracer(*s.view);
  Camera camera;
  camera.position = {0, 0, -1};
  camera.lookAt = {0, 0, 1};
  camera.vfovDegrees = 16;
  camera.width = camera.height = 24;
  camera.lensRadius = 0.2;  // out of focus the blur circle at the square is ~3 pixels
  RenderSettings settings;
  settings.samplesPerPixel = 16;
  settings.showProgress = false;
  Camera pinholeCamera = camera;
  pinholeCamera.lensRadius = 0;
  const CameraRays pinhole(pinholeCamera);
  // -1: footprint inside the square, +1: outside, 0: on its edge.
  auto footprint = [&](int x, int y) {
    int inside = 0;
    for (int k = 0; k < 4; ++k) {
      Eigen::Vector3d o, d;
      pinhole.generate(x + (k & 1), y + (k >> 1), 0, 0, o, d);
      const Eigen::Vector3d p = o + d * ((0.5 - o.z()) / d.z());
      inside += std::abs(p.x()) < 0.1 && std::abs(p.y()) < 0.1;
    }
    return inside == 4 ? -1 : inside == 0 ? 1 : 0;
  };
  camera.focusDistance = 1.5;
  const RenderOutput sharp = renderImage(camera, tracer, settings);
  camera.focusDistance = 2.0;
  const RenderOutput blurred = renderImage(camera, tracer, settings);
  int inside = 0, outside = 0, blurredInside = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const int f = footprint(x, y);
      if (f == -1) {
        ++inside;
        EXPECT_EQ(sharp.image.at(x, y).r, 0.0) << x << ", " << y;
        blurredInside += blurred.image.at(x, y).r > 0;
      } else if (f == 1) {
        ++outside;
        EXPECT_EQ(sharp.image.at(x, y).r, 1.0) << x << ", " << y;
      }
    }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 100);
  EXPECT_GT(blurredInside, 4);  // out of focus, light leaks in past the square's edge
}

// Motion blur: the square covers x in [-0.1 + 0.4t, 0.1 + 0.4t] at time t of the shutter [0, 1],
// so a ray along +z at x sees the backdrop (Le 1) for 1 − |[(x−0.1)/0.4, (x+0.1)/0.4] ∩ [0, 1]|
// of the shutter. Each sample is a Bernoulli trial: within 4σ of that.
TEST(DistributionMethod, MotionBlurAveragesCoverageOverTheShutter) {
  LoadedScene s(kData + "motion_blur.obj", kData + "motion_blur.camera.json");
  ASSERT_TRUE(s.view->hasMotion());
  const DistributionRayTracer tracer(*s.view);
  for (double x : {-0.2, -0.05, 0.0, 0.1, 0.2, 0.4, 0.45, 0.6}) {
    const double t0 = std::max(0.0, (x - 0.1) / 0.4), t1 = std::min(1.0, (x + 0.1) / 0.4);
    const double covered = std::max(0.0, t1 - t0);
    const double expected = 1 - covered;
    const int n = 3000;
    const auto [mean, error] =
        meanAndError(n, 11 + static_cast<uint64_t>(100 * (x + 1)), [&](Rng& rng) {
          RayCounts counts;
          return tracer.radiance({x, 0.02, 0}, {0, 0, 1}, rng, counts).r;
        });
    const double sigma = std::sqrt(expected * (1 - expected) / n);
    EXPECT_NEAR(mean, expected, 4 * sigma + 1e-12) << "x = " << x;
    (void)error;
  }
  // The other methods draw no time: they see the square where the OBJ puts it (time 0).
  Rng rng(3);
  RayCounts counts;
  EXPECT_EQ(DirectLighting(*s.view).radiance({0.0, 0.02, 0}, {0, 0, 1}, rng, counts).r, 0.0);
  EXPECT_EQ(DirectLighting(*s.view).radiance({0.3, 0.02, 0}, {0, 0, 1}, rng, counts).r, 1.0);
}

// The glossy lobe reflects exactly Ks at normal incidence (the (n+2)/2π normalisation), and its
// sampler's f·cosθ/pdf has the same mean: checked by uniform hemisphere sampling, which does not
// use the lobe's own sampler, and by the sampler.
TEST(GlossyLobe, ReflectsKsAtNormalIncidenceAndSamplesItsPdf) {
  Material m;
  m.illum = 2;
  m.specular = Rgb::all(0.6);
  const Eigen::Vector3d n(0, 0, 1);
  for (double exponent : {1.0, 10.0, 100.0}) {
    m.shininess = exponent;
    ASSERT_TRUE(GlossyLobe::applies(m));
    const GlossyLobe lobe(m);
    const int samples = 200000;
    const auto [uniform, uniformError] = meanAndError(samples, 5, [&](Rng& rng) {
      const double z = rng.uniform(), phi = 2 * M_PI * rng.uniform();
      const double r = std::sqrt(1 - z * z);
      const Eigen::Vector3d w(r * std::cos(phi), r * std::sin(phi), z);
      return lobe.brdf(w, n).r * z * 2 * M_PI;  // pdf 1/2π
    });
    EXPECT_NEAR(uniform, 0.6, 4 * uniformError) << "n = " << exponent;
    const auto [sampled, sampledError] = meanAndError(samples, 6, [&](Rng& rng) {
      const Eigen::Vector3d w = lobe.sample(n, rng.uniform(), rng.uniform());
      return lobe.brdf(w, n).r * w.z() / lobe.pdf(w, n);
    });
    EXPECT_NEAR(sampled, 0.6, 4 * sampledError + 1e-9) << "n = " << exponent;
  }
}

}  // namespace
}  // namespace rad
