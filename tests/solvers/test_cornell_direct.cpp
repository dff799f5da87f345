// The three iterative solvers against a direct sparse LU solve of the same system, on the
// Cornell box: each must land within the error its own stopping criterion allows.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "radiosity/pipeline/problem_setup.h"
#include "radiosity/scene/obj_loader.h"
#include "radiosity/scene/scene_mesh.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

class CornellDirect : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Scene(loadObjScene(RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj"));
    mesh_ = new PatchMesh(buildPatchMesh(*scene_));
    mesh_->subdivideUniform(mesh_->totalArea() / 400);
    rays_ = new RayCaster(*mesh_);
    method_ = new HemisphereFormFactors(*mesh_, *rays_, {256, 1});
    cache_ = new FormFactorCache(*method_);
    problem_ = new RadiosityProblem(makeProblem(*scene_, *mesh_));
    f_ = new SparseRows(gatherMatrix(*problem_, *cache_));
    direct_ = new std::vector<Rgb>(solveDirect(*problem_, *f_));
  }
  static void TearDownTestSuite() {
    delete direct_;
    delete f_;
    delete problem_;
    delete cache_;
    delete method_;
    delete rays_;
    delete mesh_;
    delete scene_;
  }

  // Area-weighted L1 difference relative to the emitted power, and the largest reflectance:
  // the error of an iterate is at most its residual / (1 − rho_max) in this norm.
  static double relativeDifference(const std::vector<Rgb>& b) {
    std::vector<Rgb> d(b.size());
    for (size_t i = 0; i < b.size(); ++i) d[i] = b[i] - (*direct_)[i];
    return relativeToEmission(*problem_, d);
  }
  static double maxReflectance() {
    double m = 0;
    for (const Rgb& r : problem_->reflectance) m = std::max(m, r.maxComponent());
    return m;
  }
  static void run(Solver& solver, double tolerance) {
    while (solver.progress() > tolerance && solver.iterations() < 1000000) solver.step();
    ASSERT_LE(solver.progress(), tolerance);
  }

  static inline Scene* scene_;
  static inline PatchMesh* mesh_;
  static inline RayCaster* rays_;
  static inline HemisphereFormFactors* method_;
  static inline FormFactorCache* cache_;
  static inline RadiosityProblem* problem_;
  static inline SparseRows* f_;
  static inline std::vector<Rgb>* direct_;
};

TEST_F(CornellDirect, DirectSolveHasZeroResidual) {
  EXPECT_LT(relativeResidual(*problem_, *f_, *direct_), 1e-10);
}

TEST_F(CornellDirect, GaussSeidelAgrees) {
  const double tolerance = 1e-6;
  GaussSeidelSolver solver(*problem_, SparseRows(*f_));
  run(solver, tolerance);
  EXPECT_LT(relativeDifference(solver.solution()), tolerance / (1 - maxReflectance()));
}

TEST_F(CornellDirect, JacobiAgrees) {
  const double tolerance = 1e-6;
  JacobiSolver solver(*problem_, SparseRows(*f_));
  run(solver, tolerance);
  EXPECT_LT(relativeDifference(solver.solution()), tolerance / (1 - maxReflectance()));
}

TEST_F(CornellDirect, SouthwellShootingAgrees) {
  const double tolerance = 1e-6;
  GatheringColumns columns(*problem_, *f_);
  ProgressiveSolver solver(*problem_, columns);
  run(solver, tolerance);
  // Unshot power U still owed at most U·rho_max/(1 − rho_max) to the solution.
  EXPECT_LT(relativeDifference(solver.solution()),
            tolerance * maxReflectance() / (1 - maxReflectance()));
}

TEST_F(CornellDirect, LazyProgressiveSolvesTheReciprocalSystem) {
  // Shooting through each shooter's row solves B = E + rho ∘ (G B) with G_ji = A_i F_ij / A_j.
  const int n = problem_->size();
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i)
    for (SparseRows::InnerIterator it(*f_, i); it; ++it)
      entries.emplace_back(static_cast<int>(it.col()), i,
                           problem_->area[i] * it.value() / problem_->area[it.col()]);
  SparseRows g(n, n);
  g.setFromTriplets(entries.begin(), entries.end());
  const std::vector<Rgb> reference = solveDirect(*problem_, g);

  const double tolerance = 1e-6;
  ProgressiveSolver solver(*problem_, *cache_);  // rows already cached: the same F
  run(solver, tolerance);
  std::vector<Rgb> d(n);
  for (int i = 0; i < n; ++i) d[i] = solver.solution()[i] - reference[i];
  EXPECT_LT(relativeToEmission(*problem_, d),
            tolerance * maxReflectance() / (1 - maxReflectance()));
}

}  // namespace
}  // namespace rad
