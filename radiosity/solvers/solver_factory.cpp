#include "radiosity/solvers/solver_factory.h"

#include <algorithm>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/solvers/gathering_solvers.h"
#include "radiosity/solvers/progressive_solver.h"

namespace rad {
namespace {

// The columns of the gathering matrix must outlive the shooting that reads them: they are a base
// constructed before the ProgressiveSolver base that refers to them.
struct OwnedColumns {
  GatheringColumns columns;
};
class SouthwellSolver final : private OwnedColumns, public ProgressiveSolver {
 public:
  SouthwellSolver(const RadiosityProblem& problem, const SparseRows& matrix)
      : OwnedColumns{GatheringColumns(problem, matrix)}, ProgressiveSolver(problem, columns) {
    setName("southwell");
  }
};

}  // namespace

const NameTable<SolverKind>& solverKindTable() {
  static const NameTable<SolverKind> table = {{"progressive", SolverKind::Progressive},
                                              {"southwell", SolverKind::Southwell},
                                              {"gauss-seidel", SolverKind::GaussSeidel},
                                              {"jacobi", SolverKind::Jacobi},
                                              {"hierarchical", SolverKind::Hierarchical}};
  return table;
}

SolverKind parseSolverKind(const std::string& name) {
  return parseName(solverKindTable(), name, "solver");
}

std::string solverKindName(SolverKind kind) { return nameOf(solverKindTable(), kind); }

std::string solverKindNames() { return joinTableNames(solverKindTable()); }

bool needsGatheringMatrix(SolverKind kind) {
  return kind != SolverKind::Progressive && kind != SolverKind::Hierarchical;
}

int defaultMaxIterations(SolverKind kind, int elements) {
  switch (kind) {
    case SolverKind::Progressive:
    case SolverKind::Southwell:
      return std::max(100000, 200 * elements);
    case SolverKind::GaussSeidel:
    case SolverKind::Jacobi:
    case SolverKind::Hierarchical:
      return 10000;
  }
  return 10000;
}

std::unique_ptr<Solver> makeSolver(SolverKind kind, const RadiosityProblem& problem,
                                   ShotRows& shots,
                                   const std::function<SparseRows()>& gatheringMatrix) {
  switch (kind) {
    case SolverKind::Progressive:
      return std::make_unique<ProgressiveSolver>(problem, shots);
    case SolverKind::Southwell:
      return std::make_unique<SouthwellSolver>(problem, gatheringMatrix());
    case SolverKind::Jacobi:
      return std::make_unique<JacobiSolver>(problem, gatheringMatrix());
    case SolverKind::GaussSeidel:
      return std::make_unique<GaussSeidelSolver>(problem, gatheringMatrix());
    case SolverKind::Hierarchical:
      break;  // links over a tree, not rows: built by the pipeline (hierarchical_solve)
  }
  RAD_CHECK(kind != SolverKind::Hierarchical);
  return nullptr;
}

}  // namespace rad
