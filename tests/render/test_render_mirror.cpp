// A mirror shows ρ_s times what the camera would see along the mirrored ray. For each eye ray
// through the mirror of data/tests/mirror_room.obj (plane z = 0.99, facing −z, Ks 0.8), the
// expected value is computed independently of the renderer's mirror code: the reflection point
// and direction come from the plane analytically, and the same integrator is asked for the
// radiance along the mirrored ray from that point. A mirror bounce draws no random numbers, so
// for the radiosity passes both estimates from the same random stream follow the same path and
// agree to rounding (so does Whitted's deterministic tracer); the path tracer is compared in the
// mean, within 4σ.
#include <gtest/gtest.h>

#include <cmath>

#include "radiosity/render/camera.h"
#include "radiosity/render/final_gather.h"
#include "radiosity/render/interpolated_preview.h"
#include "radiosity/render/path_tracer.h"
#include "radiosity/render/whitted_ray_tracer.h"
#include "tests/render/render_fixture.h"

namespace rad {
namespace {

constexpr double kMirrorZ = 0.99, kMirrorReflectance = 0.8;

// `samples` = 0: one estimate per ray from the same random stream, which must agree to rounding
// (the mirror draws no random numbers, and the integrator's decisions do not depend on the
// throughput). Otherwise (the path tracer's Russian roulette does depend on it): `samples`
// independent estimates per ray on each side, and the sums over all rays must agree within 4σ.
void expectMirrorShowsReflectedRadiance(const Integrator& integrator, double offset,
                                        const std::string& what, int samples = 0) {
  const Camera camera =
      loadCamera(std::string(RADIOSITY_DATA_DIR) + "/tests/mirror_room.camera.json");
  const CameraRays rays(camera);
  int checked = 0;
  double brightest = 0;
  Rgb sumSeen, sumDirect, varSeen, varDirect;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      Eigen::Vector3d o, d;
      rays.generate(x + 0.5, y + 0.5, 0, 0, o, d);
      const double t = (kMirrorZ - o.z()) / d.z();
      const Eigen::Vector3d p = o + t * d;
      // Well inside the mirror (0.2..0.8 in x and y), away from its edges.
      if (std::abs(p.x() - 0.5) > 0.28 || std::abs(p.y() - 0.5) > 0.28) continue;
      const Eigen::Vector3d mirrored(d.x(), d.y(), -d.z());
      // Lifted off the mirror by the caster's offset, as any ray leaving a surface is.
      const Eigen::Vector3d from = p + Eigen::Vector3d(0, 0, -offset);
      RayCounts counts;
      ++checked;
      if (samples == 0) {
        const uint64_t key = streamKey(5, y * camera.width + x);
        Rng rngEye(key), rngDirect(key);
        const Rgb seen = integrator.radiance(o, d, rngEye, counts);
        const Rgb direct = integrator.radiance(from, mirrored, rngDirect, counts);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(seen[c], kMirrorReflectance * direct[c], 1e-6 * (1 + direct[c]))
              << what << " pixel (" << x << ", " << y << ") channel " << c;
        brightest = std::max(brightest, direct.maxComponent());
        continue;
      }
      Rng rngEye(streamKey(5, y * camera.width + x, 1)),
          rngDirect(streamKey(5, y * camera.width + x, 2));
      for (int k = 0; k < samples; ++k) {
        const Rgb a = integrator.radiance(o, d, rngEye, counts);
        const Rgb b = integrator.radiance(from, mirrored, rngDirect, counts);
        sumSeen += a;
        sumDirect += b;
        varSeen += a * a;
        varDirect += b * b;
        brightest = std::max(brightest, b.maxComponent());
      }
    }
  if (samples > 0) {
    const double n = static_cast<double>(checked) * samples;
    for (int c = 0; c < 3; ++c) {
      // Variance of each sum from the per-sample second moments (the rays differ, so this
      // over-estimates slightly: a safe tolerance).
      const double vSeen = varSeen[c] - sumSeen[c] * sumSeen[c] / n;
      const double vDirect = varDirect[c] - sumDirect[c] * sumDirect[c] / n;
      const double sigma = std::sqrt(vSeen + kMirrorReflectance * kMirrorReflectance * vDirect);
      EXPECT_NEAR(sumSeen[c], kMirrorReflectance * sumDirect[c], 4 * sigma)
          << what << " channel " << c;
    }
  }
  EXPECT_GT(checked, 100);    // the mirror fills much of the view
  EXPECT_GT(brightest, 0.1);  // and shows a lit room, not black
}

class MirrorRoom : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SolveOptions o;
    o.targetElements = 600;
    o.raysPerElement = 256;
    scene_ = testing::solveForRender(std::string(RADIOSITY_DATA_DIR) + "/tests/mirror_room.obj", o)
                 .release();
  }
  static void TearDownTestSuite() { delete scene_; }
  static testing::SolvedScene* scene_;
};
testing::SolvedScene* MirrorRoom::scene_ = nullptr;

TEST_F(MirrorRoom, InterpolatedRadiosityInTheMirror) {
  expectMirrorShowsReflectedRadiance(
      InterpolatedPreview(*scene_->view, scene_->solved.solution.radiosity),
      scene_->caster->surfaceOffset(), "gather 0");
}

TEST_F(MirrorRoom, FinalGatherInTheMirror) {
  expectMirrorShowsReflectedRadiance(
      FinalGather(*scene_->view, scene_->solved.solution.radiosity, {8}),
      scene_->caster->surfaceOffset(), "gather 8");
}

TEST_F(MirrorRoom, PathTracerInTheMirror) {
  expectMirrorShowsReflectedRadiance(PathTracer(*scene_->view), scene_->caster->surfaceOffset(),
                                     "path", 64);
}

// Whitted's tracer is deterministic: the mirrored view agrees to rounding.
TEST_F(MirrorRoom, WhittedInTheMirror) {
  expectMirrorShowsReflectedRadiance(WhittedRayTracer(*scene_->view),
                                     scene_->caster->surfaceOffset(), "whitted");
}

}  // namespace
}  // namespace rad
