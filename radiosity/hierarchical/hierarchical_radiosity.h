#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/hierarchical/hierarchical_solver.h"
#include "radiosity/hierarchical/link_form_factors.h"
#include "radiosity/hierarchical/link_oracle.h"
#include "radiosity/hierarchical/link_set.h"
#include "radiosity/hierarchical/node_hierarchy.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

struct HierarchicalOptions {
  // The most light one link may carry, over the emitted power per element (emitted power /
  // elements): a per-link bound that tightens as the mesh grows, since the links' errors add up.
  double linkEpsilon = 0.01;
  int raysPerReceiver = 1024;
  uint64_t seed = 1;
  const ElementExposure* exposure = nullptr;  // optional; must outlive the solve
};

// Hierarchical radiosity with clustering over a meshed problem: owns the tree, the links and the
// solver. Construction links every input patch to the root (LinkOracle from B = E, the threshold
// linkEpsilon × emitted power / elements), casts the receivers' rays (LinkFormFactors) and starts
// the solver; refineLinks() is BF refinement between solves.
class HierarchicalRadiosity {
 public:
  HierarchicalRadiosity(const PatchMesh& mesh, const RayCaster& rays,
                        const RadiosityProblem& problem, HierarchicalOptions options);

  HierarchicalSolver& solver() { return *solver_; }
  const HierarchicalSolver& solver() const { return *solver_; }
  // Splits the links the solver's current B makes carry more than the threshold, casts the rays
  // of the receivers whose links changed, and moves the solver over to the new links (its B
  // kept). Returns the links split; 0: every link passes and nothing changed.
  int64_t refineLinks();

  const NodeHierarchy& tree() const { return tree_; }
  const LinkSet& links() const { return *links_; }
  uint64_t raysCast() const { return raysCast_; }
  int passes() const { return passes_; }             // link sets made: 1 + refinements
  int64_t linksRefined() const { return refined_; }  // links split over all refinements
  // The memory the tree, the links and the solver's values hold.
  size_t bytes() const { return tree_.bytes() + links_->bytes() + solver_->bytes(); }

 private:
  const RadiosityProblem& problem_;
  NodeHierarchy tree_;
  std::vector<float> reflectance_, radiosity_;  // per node, for the oracle
  LinkOracle oracle_;
  LinkFormFactors factors_;
  std::unique_ptr<LinkSet> links_;
  std::unique_ptr<HierarchicalSolver> solver_;
  uint64_t raysCast_ = 0;
  int passes_ = 1;
  int64_t refined_ = 0;
};

}  // namespace rad
