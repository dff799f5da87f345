// Scale and position invariance: radiosity is dimensionless in the geometry (F_ij depends only on
// shapes, E = pi·Ke does not depend on size), so the Cornell box scaled by 1e-3 or 1e4, or moved
// 1e6 units away, must give the same radiosity. Compared per patch (input polygon: the same in
// every run) as the area-weighted mean over its elements, emitters excluded, each averaged over
// kSeeds seeds, against the Monte Carlo noise of that average: the difference between two such
// averages over other seeds at the original scale. (The element's random streams are keyed by
// its corners, so a scaled run draws other rays than the unscaled one with the same seed: the two
// are independent estimates.) Under no systematic error both differences are draws of the same
// noise over the same ~20 patches: their RMS ratio stays below 2.5 with better than 99.9%
// confidence (F-distribution of the squared ratio with about 20 degrees of freedom each). An
// absolute ray offset or a precision loss in the BVH would show as light leaking or missing at
// the corners: a systematic difference that averaging over seeds does not shrink.
//
// The meshing itself is checked too: longest-edge bisection must pick the same edges whatever
// the scale (equal lengths within rounding are ties, broken by edge index).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "radiosity/core/log.h"
#include "radiosity/pipeline/solve_pipeline.h"
#include "radiosity/scene/obj_loader.h"

namespace rad {
namespace {

SolveOptions smallOptions(uint64_t seed) {
  SolveOptions options;
  options.targetElements = 400;
  options.raysPerElement = 256;
  options.threads = 2;
  options.seed = seed;
  return options;
}

// Area-weighted mean radiosity (luminance) of each patch.
std::vector<double> patchMeans(const SolveResult& r) {
  std::vector<double> sum(r.solution.mesh->patchCount(), 0), area(r.solution.mesh->patchCount(), 0);
  for (int e = 0; e < r.solution.mesh->elementCount(); ++e) {
    sum[r.solution.mesh->patch(e)] +=
        r.solution.problem.area[e] * r.solution.radiosity[e].luminance();
    area[r.solution.mesh->patch(e)] += r.solution.problem.area[e];
  }
  for (size_t p = 0; p < sum.size(); ++p) sum[p] /= area[p];
  return sum;
}

constexpr int kSeeds = 4;

// The patch means averaged over kSeeds solves of `scene` with seeds first, first + 1, ...
std::vector<double> averagedPatchMeans(const Scene& scene, uint64_t first) {
  std::vector<double> sum;
  for (int k = 0; k < kSeeds; ++k) {
    const std::vector<double> means = patchMeans(solveScene(scene, smallOptions(first + k)));
    sum.resize(means.size(), 0);
    for (size_t p = 0; p < means.size(); ++p) sum[p] += means[p] / kSeeds;
  }
  return sum;
}

// Relative RMS difference of patch means, emitting patches (`emits`) excluded (their B is mostly
// E).
double relativeRms(const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<char>& emits) {
  double num = 0, den = 0;
  for (size_t p = 0; p < y.size(); ++p)
    if (!emits[p]) {
      num += (x[p] - y[p]) * (x[p] - y[p]);
      den += y[p] * y[p];
    }
  return std::sqrt(num / den);
}

class ScaleInvariance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    setLogLevel(LogLevel::Quiet);
    scene_ = new Scene(loadObjScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj"));
    reference_ = new SolveResult(solveScene(*scene_, smallOptions(1)));
    emits_.assign(reference_->solution.mesh->patchCount(), 0);
    for (int e = 0; e < reference_->solution.mesh->elementCount(); ++e)
      if (reference_->solution.problem.emission[e].maxComponent() > 0)
        emits_[reference_->solution.mesh->patch(e)] = 1;
    referenceMeans_ = averagedPatchMeans(*scene_, 1);
    seedNoise_ = relativeRms(averagedPatchMeans(*scene_, 1 + kSeeds), referenceMeans_, emits_);
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete scene_;
  }

  void expectSameAsReference(double scale, const Eigen::Vector3d& offset) {
    Scene moved = *scene_;
    for (Eigen::Vector3d& p : moved.positions) p = p * scale + offset;
    const SolveResult result = solveScene(moved, smallOptions(1));
    ASSERT_EQ(result.solution.mesh->patchCount(), reference_->solution.mesh->patchCount());
    for (const Rgb& b : result.solution.radiosity)
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(b[c]));
    const double d = relativeRms(averagedPatchMeans(moved, 1), referenceMeans_, emits_);
    std::cout << "scale " << scale << ", offset " << offset.norm() << ": relative RMS difference "
              << d << " (seed-to-seed noise of the " << kSeeds << "-seed means " << seedNoise_
              << ")\n";
    EXPECT_LT(d, 2.5 * seedNoise_);
  }

  static inline Scene* scene_;
  static inline SolveResult* reference_;
  static inline std::vector<char> emits_;
  static inline std::vector<double> referenceMeans_;
  static inline double seedNoise_ = 0;
};

TEST_F(ScaleInvariance, SeedNoiseIsSmall) {
  std::cout << "seed-to-seed relative RMS difference of the patch means: " << seedNoise_ << "\n";
  EXPECT_GT(seedNoise_, 0);
  EXPECT_LT(seedNoise_, 0.05);  // else the comparison above would be meaningless
}
TEST_F(ScaleInvariance, ScaledDownByOneThousand) {
  expectSameAsReference(1e-3, Eigen::Vector3d::Zero());
}
TEST_F(ScaleInvariance, ScaledUpByTenThousand) {
  expectSameAsReference(1e4, Eigen::Vector3d::Zero());
}
TEST_F(ScaleInvariance, TranslatedByOneMillion) {
  expectSameAsReference(1, Eigen::Vector3d(1e6, -1e6, 1e6));
}
TEST_F(ScaleInvariance, ScaledDownAndFarAway) {
  expectSameAsReference(1e-3, Eigen::Vector3d(1e3, 0, 0));
}

// The same polygons scaled by 1e-3 must give the same elements (centroids scaled by 1e-3):
// longestEdge() treats lengths equal within rounding as ties, broken by edge index.
TEST_F(ScaleInvariance, MeshingDoesNotDependOnScale) {
  Scene scaled = *scene_;
  for (Eigen::Vector3d& p : scaled.positions) p *= 1e-3;
  const SolveResult result = solveScene(scaled, smallOptions(1));
  const PatchMesh& a = *reference_->solution.mesh;
  const PatchMesh& b = *result.solution.mesh;
  ASSERT_EQ(a.elementCount(), b.elementCount());
  int different = 0;
  for (int e = 0; e < a.elementCount(); ++e) {
    const auto ca = a.corners(e), cb = b.corners(e);
    const Eigen::Vector3d da = (ca[0] + ca[1] + ca[2]) / 3, db = (cb[0] + cb[1] + cb[2]) / 3e-3;
    different += (da - db).norm() > 1e-9;
  }
  EXPECT_EQ(different, 0) << "of " << a.elementCount() << " elements";
}

}  // namespace
}  // namespace rad
