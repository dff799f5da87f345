#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "radiosity/hierarchical/node_hierarchy.h"

namespace rad {

// One link of hierarchical radiosity: light gathered by its receiver node from `source`,
// F = the form factor from the receiver to the source's leaves (receiver's area average).
//
// `seen` keeps where the link's rays met the source: the shares of its hits in each of the
// source's grandchildren (kSeenParts, 8 bits each, normalised when read), so the solve reads the
// source as its rays saw it rather than as its area average. Parts of a source that are both
// darker and harder to see (its corners, the floor between boxes) otherwise count at their full
// area: the generated room of 64 boxes came out 1.2% dark at the default --link-epsilon and 2.2%
// at 0.1 (measured against a path-traced reference), each link's error leaning the same way.
struct Link {
  static constexpr int kSeenDepth = 2;  // grandchildren
  static constexpr int kSeenParts = 1 << kSeenDepth;
  int source = -1;
  float factor = 0;
  std::array<uint8_t, kSeenParts> seen{};
};

// Which of the source's kSeenParts parts holds the leaf at `leafPosition` (one of its leaves),
// and the node of part `part`: the grandchild along the part's bits, or the leaf the way stops at.
int seenPart(const NodeHierarchy& tree, int source, int leafPosition);
int seenPartNode(const NodeHierarchy& tree, int source, int part);

// A receiver node and a source node to link.
using NodePair = std::pair<int, int>;

// The links, grouped by receiver node (compressed rows: 12 bytes a link, 8 a node). A receiver's
// links are sorted by their sources' first leaf, so the link holding a leaf is found by binary
// search: the sources linked to one receiver are disjoint subtrees.
class LinkSet {
 public:
  LinkSet() = default;
  // From (receiver, source) pairs, each at most once; factors start at 0.
  LinkSet(const NodeHierarchy& tree, std::vector<NodePair>&& pairs);

  int64_t size() const { return static_cast<int64_t>(links_.size()); }
  int64_t begin(int receiver) const { return begin_[receiver]; }
  int64_t end(int receiver) const { return begin_[receiver + 1]; }
  bool hasLinks(int receiver) const { return end(receiver) > begin(receiver); }
  // The share of a receiver's rays whose first hit lies in a source linked to one of its
  // ancestors: the same quantity its ancestors' factors estimate from their own rays, measured
  // from this receiver's (HierarchicalSolver's correction).
  float aboveFraction(int receiver) const { return aboveFraction_[receiver]; }
  void setAboveFraction(int receiver, float f) { aboveFraction_[receiver] = f; }
  const Link& operator[](int64_t k) const { return links_[k]; }
  Link& operator[](int64_t k) { return links_[k]; }
  // The receivers that hold links, in node order.
  std::vector<int> receivers() const;
  // The link of `receiver` whose source holds the leaf at `leafPosition`; -1 when none does.
  int64_t find(const NodeHierarchy& tree, int receiver, int leafPosition) const;
  size_t bytes() const {
    return begin_.capacity() * sizeof(int64_t) + links_.capacity() * sizeof(Link) +
           aboveFraction_.capacity() * sizeof(float);
  }

 private:
  std::vector<int64_t> begin_;
  std::vector<Link> links_;
  std::vector<float> aboveFraction_;  // per node
};

}  // namespace rad
