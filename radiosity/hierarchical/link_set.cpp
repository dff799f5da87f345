#include "radiosity/hierarchical/link_set.h"

#include <algorithm>

#include "radiosity/core/check.h"

namespace rad {

LinkSet::LinkSet(const NodeHierarchy& tree, std::vector<NodePair>&& pairs) {
  std::sort(pairs.begin(), pairs.end(), [&](const NodePair& a, const NodePair& b) {
    return a.first < b.first ||
           (a.first == b.first && tree.node(a.second).leafBegin < tree.node(b.second).leafBegin);
  });
  begin_.assign(static_cast<size_t>(tree.size()) + 1, 0);
  aboveFraction_.assign(tree.size(), 0.0f);
  for (const NodePair& p : pairs) ++begin_[p.first + 1];
  for (int n = 0; n < tree.size(); ++n) begin_[n + 1] += begin_[n];
  links_.resize(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) {
    links_[k].source = pairs[k].second;
    // The sources of one receiver are disjoint subtrees (the refinement's partition).
    if (k > 0 && pairs[k - 1].first == pairs[k].first)
      RAD_CHECK(tree.node(pairs[k - 1].second).leafEnd <= tree.node(pairs[k].second).leafBegin);
  }
  std::vector<NodePair>().swap(pairs);
}

int seenPart(const NodeHierarchy& tree, int source, int leafPosition) {
  int part = 0;
  for (int level = 0; level < Link::kSeenDepth; ++level) {
    const HierarchyNode& node = tree.node(source);
    const bool second = !node.isLeaf() && leafPosition >= tree.node(node.child[0]).leafEnd;
    part = 2 * part + (second ? 1 : 0);
    if (!node.isLeaf()) source = node.child[second ? 1 : 0];
  }
  return part;
}

int seenPartNode(const NodeHierarchy& tree, int source, int part) {
  for (int level = Link::kSeenDepth - 1; level >= 0; --level) {
    const HierarchyNode& node = tree.node(source);
    if (node.isLeaf()) break;
    source = node.child[(part >> level) & 1];
  }
  return source;
}

std::vector<int> LinkSet::receivers() const {
  std::vector<int> out;
  for (int n = 0; n + 1 < static_cast<int>(begin_.size()); ++n)
    if (hasLinks(n)) out.push_back(n);
  return out;
}

int64_t LinkSet::find(const NodeHierarchy& tree, int receiver, int leafPosition) const {
  const auto first = links_.begin() + begin(receiver), last = links_.begin() + end(receiver);
  // The first link whose source starts after the leaf; the one before it may hold the leaf.
  const auto after = std::upper_bound(first, last, leafPosition, [&](int pos, const Link& l) {
    return pos < tree.node(l.source).leafBegin;
  });
  if (after == first) return -1;
  const auto holder = after - 1;
  return leafPosition < tree.node(holder->source).leafEnd ? holder - links_.begin() : -1;
}

}  // namespace rad
