#pragma once

#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <string>

#include "radiosity/core/named_values.h"
#include "radiosity/formfactors/shot_rows.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// The ways of solving the radiosity system that the command line offers.
// Hierarchical radiosity links nodes of a tree over the elements instead of element rows: the
// pipeline builds it (pipeline/hierarchical_solve), not makeSolver.
enum class SolverKind { Progressive, Southwell, GaussSeidel, Jacobi, Hierarchical };
// The solvers' command-line names ("progressive", "gauss-seidel", ...), the one list of them.
const NameTable<SolverKind>& solverKindTable();
SolverKind parseSolverKind(const std::string& name);  // InputError naming the known ones
std::string solverKindName(SolverKind kind);
// "progressive | southwell | gauss-seidel | jacobi | hierarchical", for help texts.
std::string solverKindNames();
// Whether the solver needs every row of the gathering matrix before its first step.
bool needsGatheringMatrix(SolverKind kind);
// The iteration budget a solver gets when --max-iterations is not given.
int defaultMaxIterations(SolverKind kind, int elements);

// The one place solvers are built. Progressive shooting reads `shots` lazily; the gathering
// solvers (Jacobi, Gauss–Seidel, and Southwell, which shoots along the matrix's columns) call
// `gatheringMatrix` once, here. The solver keeps references to `problem` and `shots`.
std::unique_ptr<Solver> makeSolver(
    SolverKind kind, const RadiosityProblem& problem, ShotRows& shots,
    const std::function<Eigen::SparseMatrix<double, Eigen::RowMajor>()>& gatheringMatrix);

}  // namespace rad
