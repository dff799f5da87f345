#pragma once

#include <Eigen/SparseCore>

#include "radiosity/formfactors/form_factor_cache.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/solvers/solver.h"

namespace rad {

using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Builds F for a gathering solver: computes (in parallel) the rows of every reflecting element.
// Rows of black elements are skipped: they receive but never pass light on.
SparseRows gatherMatrix(const RadiosityProblem& problem, FormFactorCache& cache,
                        Progress* progress = nullptr);

// What Jacobi and Gauss–Seidel share: the gathering rows, the current B (starting at B_0 = E)
// and the relative residual, recomputed exactly after every sweep.
class GatheringSolver : public Solver {
 public:
  double progress() const override { return residual_; }
  const std::vector<Rgb>& solution() const override { return solution_; }
  int iterations() const override { return iterations_; }
  std::string progressMeasure() const override { return "relative residual"; }
  // F E by the rows (a black element's row is never computed: 0 there).
  std::vector<Rgb> irradianceFrom(const std::vector<Rgb>& emission) override;
  // Iterates on from `guess` instead of B_0 = E (one B per element): `update` starts from the
  // solution before the edit, which is already right wherever the edit changed nothing.
  void startFrom(std::vector<Rgb> guess);
  // Hands F back (swapped out, no copy) once iterating is done; the solver must not step again.
  SparseRows releaseMatrix();

 protected:
  // Takes the matrix over (swapped in: Eigen 3.4's SparseMatrix "move" copies every entry, which
  // costs seconds on a large scene's F).
  GatheringSolver(const RadiosityProblem& problem, SparseRows&& formFactors);
  void finishSweep();  // counts the sweep and updates the residual

  const RadiosityProblem& problem_;
  SparseRows f_;
  std::vector<Rgb> solution_;
  double residual_ = 0;
  int iterations_ = 0;
};

// Jacobi iteration B_{k+1} = E + rho ∘ (F B_k), from B_0 = E: iteration k adds the k-th bounce
// of light, so after k steps B_k = sum_{m<=k} (rho F)^m E exactly (the Neumann series).
class JacobiSolver : public GatheringSolver {
 public:
  JacobiSolver(const RadiosityProblem& problem, SparseRows&& formFactors)
      : GatheringSolver(problem, std::move(formFactors)) {}
  std::string name() const override { return "jacobi"; }
  void step() override;
};

// Gauss–Seidel: sweeps the rows in order, using each freshly updated B_j at once; converges
// about twice as fast as Jacobi for the same work. Handles a non-zero F_ii exactly.
class GaussSeidelSolver : public GatheringSolver {
 public:
  GaussSeidelSolver(const RadiosityProblem& problem, SparseRows&& formFactors)
      : GatheringSolver(problem, std::move(formFactors)) {}
  std::string name() const override { return "gauss-seidel"; }
  void step() override;
};

// r = E + rho ∘ (F B) − B, relative to the emission (see relativeToEmission).
double relativeResidual(const RadiosityProblem& problem, const SparseRows& f,
                        const std::vector<Rgb>& b);

// Reference solution of (I − diag(rho) F) B = E per channel by sparse LU (Eigen::SparseLU).
std::vector<Rgb> solveDirect(const RadiosityProblem& problem, const SparseRows& f);

}  // namespace rad
