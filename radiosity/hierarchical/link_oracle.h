#pragma once

#include <vector>

#include "radiosity/hierarchical/link_set.h"
#include "radiosity/hierarchical/node_hierarchy.h"

namespace rad {

// The refinement oracle of hierarchical radiosity (BF refinement, Hanrahan et al. 1991): a pair
// of nodes is linked where the light the link would carry, ρ_r · B_s · F_rs · A_r, is at most the
// threshold; otherwise the larger of the two (by bounding sphere) is split and its children are
// linked in its place, down to single elements. F_rs is estimated without rays, from the
// centroids: A_s cos_r cos_s / (π d² + A_s), each cosine raised by the other node's angular size,
// and 1 for a cluster's or for nodes whose bounding spheres overlap (where the estimate says
// nothing). A source wholly behind the receiver's plane, or a receiver wholly behind a surface
// source's plane, exchanges no light and is never linked; nor are two nodes of one (planar) patch.
// Receivers are surface nodes and leaves only: a cluster's elements face every way, so they
// gather separately.
class LinkOracle {
 public:
  // `radiosity`: per node, B summed over the channels (area average over its leaves);
  // `reflectance`: per node, the largest channel of ρ over its leaves; `threshold`: the power a
  // link may carry, in the units of B × area.
  LinkOracle(const NodeHierarchy& tree, const std::vector<float>& radiosity,
             const std::vector<float>& reflectance, double threshold)
      : tree_(tree), radiosity_(radiosity), reflectance_(reflectance), threshold_(threshold) {}

  // Links `receiver` to `source` or to their descendants, refining until each link passes;
  // appends the links made.
  void link(int receiver, int source, std::vector<NodePair>& out) const;
  // Whether an existing link still passes with the current radiosity (leaf pairs always do).
  bool passes(int receiver, int source) const;

 private:
  enum class Exchange { None, Estimated, Near };
  // The light a link would carry, and whether the pair exchanges any at all.
  Exchange estimate(int receiver, int source, double& power) const;

  const NodeHierarchy& tree_;
  const std::vector<float>& radiosity_;
  const std::vector<float>& reflectance_;
  double threshold_;
};

}  // namespace rad
