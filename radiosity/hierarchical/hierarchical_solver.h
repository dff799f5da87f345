#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/hierarchical/directional_clusters.h"
#include "radiosity/hierarchical/link_set.h"
#include "radiosity/hierarchical/node_hierarchy.h"
#include "radiosity/solvers/radiosity_problem.h"
#include "radiosity/solvers/solver.h"

namespace rad {

// Gauss–Seidel over the links of hierarchical radiosity. One step is a sweep over the input
// patches: each gathers at every node of its tree, Σ F·B_source over the node's links (the
// light arriving, not yet reflected), pushes what it gathered down to the leaves, where
// B = E + ρ · (the gathered sum of the leaf and all its ancestors), and pulls B back up as area
// averages; the clusters above the patch take the change at once, so later patches gather from
// the new values. The measure is the relative residual of the hierarchical system:
// Σ A |E + ρ·gathered(B) − B| / emitted power, evaluated after every sweep.
//
// The ancestors' correction: a leaf's factors, summed over its own and its ancestors' links, come
// from the rays of several receivers, each an area average over a different node, so they need
// not add up as one element's row does (a closed furnace's leaves were up to 18% off). The deepest
// receiver above a leaf also counts its own rays that reach its ancestors' sources; at the leaf,
// the ancestors' gather is scaled by that share over the ancestors' factor sum. The ancestors keep
// the distribution over their sources, the deepest receiver's rays set how much of its hemisphere
// those sources fill, and a furnace gives E/(1 − ρ) at every leaf. The scale is linear in the
// deepest receiver's count, so it adds no bias of its own (a normalisation by the leaf's whole
// factor sum did, Jensen's: +1–2% on the Cornell box).
class HierarchicalSolver : public Solver {
 public:
  // Keeps references to all three; the links' factors must be set.
  HierarchicalSolver(const NodeHierarchy& tree, const LinkSet& links,
                     const RadiosityProblem& problem);

  std::string name() const override { return "hierarchical"; }
  void step() override;
  double progress() const override { return residual_; }
  const std::vector<Rgb>& solution() const override { return solution_; }
  // Empty: a link gathers a source node's B as its rays saw it and a cluster's as its bins show
  // it, so the links cannot carry another emission (hierarchical_solve keeps the emitters' shadow
  // rays' E_d instead).
  std::vector<Rgb> irradianceFrom(const std::vector<Rgb>&) override { return {}; }
  int iterations() const override { return iterations_; }
  std::string progressMeasure() const override { return "relative residual"; }

  // Takes over another solver's B and iteration count (the same tree, before its links were
  // refined) and evaluates the residual over this one's links.
  void continueFrom(const HierarchicalSolver& other);
  // The memory its per-node and per-element values hold, for the report.
  size_t bytes() const {
    return (nodeB_.capacity() + solution_.capacity()) * sizeof(Rgb) +
           scale_.capacity() * sizeof(float) + clusters_.bytes();
  }
  // B per node (area averages over its leaves), as the oracle and the viewer read it.
  const std::vector<Rgb>& nodeRadiosity() const { return nodeB_; }
  // What link k of `receiver` brings it from the current B, before ρ: F · the source's B as the
  // link's rays saw it (its parts weighted by their hits, Link::seen), a cluster's as it shows
  // towards the receiver (its bins). A node gathers the sum of its links'.
  Rgb linkGather(int receiver, int64_t k) const;
  // Element e's correction of what the receivers above its deepest receiver gathered (the class
  // comment): B_e = E + ρ · (the deepest receiver's and its descendants' gather + this × the
  // gather of the receivers above it).
  float ancestorScale(int element) const { return scale_[element]; }

 private:
  // Node s's B as a receiver sees it: a cluster's by its bins towards the receiver.
  Rgb radianceSeen(int receiver, int s) const;
  Rgb gathered(int node) const;
  // Pushes `above` (gathered by the ancestors) plus the node's own gather to its leaves, sets B
  // there and on the way back up; returns the node's A·B.
  // `aboveDeepest`: what the ancestors of the deepest receiver on the way down gathered.
  Rgb pushPull(int node, const Rgb& above, const Rgb& aboveDeepest);
  // B = E + ρ·gathered at every leaf from the current node values, without changing them:
  // Σ A |change| over the leaves.
  double residualNorm() const;
  void residualOf(int node, const Rgb& above, const Rgb& aboveDeepest, double& sum) const;
  void pullClusters();
  void updateResidual();
  void normalise(int node, double factorsAbove, float foreign, float above);

  const NodeHierarchy& tree_;
  const LinkSet& links_;
  const RadiosityProblem& problem_;
  DirectionalClusters clusters_;
  std::vector<Rgb> nodeB_;
  std::vector<Rgb> solution_;  // per element
  std::vector<float> scale_;   // per element: the ancestors' gather's correction (normalise)
  double residual_ = 1;
  int iterations_ = 0;
};

}  // namespace rad
