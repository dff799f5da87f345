#pragma once

#include <algorithm>
#include <vector>

#include "radiosity/hierarchical/link_set.h"
#include "radiosity/hierarchical/node_hierarchy.h"

namespace rad {

// The refinement oracle of hierarchical radiosity (BF refinement, Hanrahan et al. 1991): a pair
// of nodes is linked where the light the link would carry, ρ_r · B_s · F_rs · A_r, is at most the
// threshold; otherwise the larger of the two (by bounding sphere) is split and its children are
// linked in its place, down to single elements. F_rs is estimated without rays, from the
// centroids: A_s cos_r cos_s / (π d² + A_s) (for a cluster, A_s at most its bounding sphere's
// cross-section), each cosine raised by the other node's angular size,
// and 1 for a cluster's or for nodes whose bounding spheres overlap (where the centroids' cosines
// say nothing). A source whose
// estimated F would bring the receiver fewer than one of its rays is linked as it is: its parts'
// factors could not be told apart by those rays (this caps a receiver's links near its rays). A
// source wholly behind the receiver's plane, or a receiver wholly behind a surface source's plane,
// exchanges no light and is never linked; nor are two nodes of one (planar) patch. Receivers are
// surface nodes and leaves only: a cluster's elements face every way, so they gather separately.
class LinkOracle {
 public:
  // `radiosity`: per node, B summed over the channels (area average over its leaves);
  // `reflectance`: per node, the largest channel of ρ over its leaves; `threshold`: the power a
  // link may carry, in the units of B × area, summed over the channels as `radiosity` is.
  // `rays`: each receiver's rays; a source that fewer than one of them would reach is not split.
  // `meanArea`: the elements' mean area; a receiver larger than that may carry proportionally
  // more (the same bound on the radiosity a link adds to it), so that a few large elements among
  // many small ones do not need links to every small one.
  LinkOracle(const NodeHierarchy& tree, const std::vector<float>& radiosity,
             const std::vector<float>& reflectance, double threshold, int rays, double meanArea)
      : tree_(tree),
        radiosity_(radiosity),
        reflectance_(reflectance),
        threshold_(threshold),
        rays_(rays),
        meanArea_(meanArea) {}

  // Links `receiver` to `source` or to their descendants, refining until each link passes;
  // appends the links made.
  void link(int receiver, int source, std::vector<NodePair>& out) const;
  // Whether an existing link still passes with the current radiosity (leaf pairs always do).
  bool passes(int receiver, int source) const;

 private:
  // None: no light passes; Unresolved: too small for the receiver's rays to tell its parts apart.
  enum class Exchange { None, Estimated, Unresolved };
  // The light a link would carry, and whether the pair exchanges any at all.
  Exchange estimate(int receiver, int source, double& power) const;

  const NodeHierarchy& tree_;
  const std::vector<float>& radiosity_;
  const std::vector<float>& reflectance_;
  double thresholdFor(int receiver) const {
    return meanArea_ > 0 ? threshold_ * std::max(1.0, tree_.node(receiver).area / meanArea_)
                         : threshold_;
  }

  double threshold_;
  int rays_;
  double meanArea_;
};

}  // namespace rad
