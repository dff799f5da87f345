#include "radiosity/solvers/gathering_solvers.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/SparseLU>
#include <stdexcept>

#include "radiosity/core/check.h"

namespace rad {
namespace {
Rgb gatherRow(const SparseRows& f, int i, const std::vector<Rgb>& b) {
  Rgb sum;
  for (SparseRows::InnerIterator it(f, i); it; ++it) sum += it.value() * b[it.col()];
  return sum;
}
}  // namespace

SparseRows gatherMatrix(const RadiosityProblem& problem, FormFactorCache& cache,
                        Progress* progress) {
  cache.computeRows(problem.reflecting(), progress);
  return cache.matrix();
}

double relativeResidual(const RadiosityProblem& problem, const SparseRows& f,
                        const std::vector<Rgb>& b) {
  // Each element's residual on its own: side by side (a pass over F as long as a sweep's).
  std::vector<Rgb> r(problem.size());
  tbb::parallel_for(
      tbb::blocked_range<int>(0, problem.size(), 256), [&](const tbb::blocked_range<int>& range) {
        for (int i = range.begin(); i != range.end(); ++i)
          r[i] = problem.emission[i] + problem.reflectance[i] * gatherRow(f, i, b) - b[i];
      });
  return relativeToEmission(problem, r);
}

GatheringSolver::GatheringSolver(const RadiosityProblem& problem, SparseRows&& formFactors)
    : problem_(problem), solution_(problem.emission) {
  f_.swap(formFactors);
  residual_ = relativeResidual(problem_, f_, solution_);
}

void GatheringSolver::startFrom(std::vector<Rgb> guess) {
  RAD_CHECK_EQ(guess.size(), solution_.size());
  solution_ = std::move(guess);
  residual_ = relativeResidual(problem_, f_, solution_);
}

std::vector<Rgb> GatheringSolver::irradianceFrom(const std::vector<Rgb>& emission) {
  RAD_CHECK_EQ(emission.size(), solution_.size());
  RAD_CHECK_MSG(f_.rows() == problem_.size(), "the matrix was released");
  std::vector<Rgb> irradiance(emission.size());
  tbb::parallel_for(tbb::blocked_range<int>(0, problem_.size(), 256),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int i = range.begin(); i != range.end(); ++i)
                        irradiance[i] = gatherRow(f_, i, emission);
                    });
  return irradiance;
}

SparseRows GatheringSolver::releaseMatrix() {
  SparseRows f;
  f.swap(f_);
  return f;
}

void GatheringSolver::finishSweep() {
  ++iterations_;
  residual_ = relativeResidual(problem_, f_, solution_);
}

void JacobiSolver::step() {
  RAD_CHECK_MSG(f_.rows() == problem_.size(), "no matrix: it was released");
  std::vector<Rgb> next(problem_.size());
  tbb::parallel_for(
      tbb::blocked_range<int>(0, problem_.size(), 256), [&](const tbb::blocked_range<int>& range) {
        for (int i = range.begin(); i != range.end(); ++i)
          next[i] = problem_.emission[i] + problem_.reflectance[i] * gatherRow(f_, i, solution_);
      });
  solution_.swap(next);
  finishSweep();
}

void GaussSeidelSolver::step() {
  RAD_CHECK_MSG(f_.rows() == problem_.size(), "no matrix: it was released");
  for (int i = 0; i < problem_.size(); ++i) {
    Rgb others;
    double selfFactor = 0;
    for (SparseRows::InnerIterator it(f_, i); it; ++it) {
      if (it.col() == i)
        selfFactor = it.value();
      else
        others += it.value() * solution_[it.col()];
    }
    const Rgb& rho = problem_.reflectance[i];
    const Rgb numerator = problem_.emission[i] + rho * others;
    solution_[i] = {numerator.r / (1 - rho.r * selfFactor), numerator.g / (1 - rho.g * selfFactor),
                    numerator.b / (1 - rho.b * selfFactor)};
  }
  finishSweep();
}

std::vector<Rgb> solveDirect(const RadiosityProblem& problem, const SparseRows& f) {
  const int n = problem.size();
  std::vector<Rgb> b(n);
  for (int c = 0; c < 3; ++c) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) {
      entries.emplace_back(i, i, 1.0);
      for (SparseRows::InnerIterator it(f, i); it; ++it)
        entries.emplace_back(i, static_cast<int>(it.col()),
                             -problem.reflectance[i][c] * it.value());
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(a);
    if (lu.info() != Eigen::Success) throw std::runtime_error("sparse LU factorisation failed");
    Eigen::VectorXd e(n);
    for (int i = 0; i < n; ++i) e[i] = problem.emission[i][c];
    const Eigen::VectorXd x = lu.solve(e);
    for (int i = 0; i < n; ++i) b[i][c] = x[i];
  }
  return b;
}

}  // namespace rad
