#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "radiosity/hierarchical/node_hierarchy.h"

namespace rad {

// One link of hierarchical radiosity: light gathered by its receiver node from `source`,
// F = the form factor from the receiver to the source's leaves (receiver's area average).
struct Link {
  int source = -1;
  float factor = 0;
};

// A receiver node and a source node to link.
using NodePair = std::pair<int, int>;

// The links, grouped by receiver node (compressed rows: 8 bytes a link, 8 a node). A receiver's
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
