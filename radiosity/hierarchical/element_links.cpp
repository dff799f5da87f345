#include "radiosity/hierarchical/element_links.h"

#include "radiosity/core/check.h"

namespace rad {

ElementLinks::ElementLinks(const HierarchicalRadiosity& solved) : links_(solved.links()) {
  const NodeHierarchy& tree = solved.tree();
  const HierarchicalSolver& solver = solved.solver();
  nodes_.resize(tree.size());
  for (int n = 0; n < tree.size(); ++n) {
    const HierarchyNode& node = tree.node(n);
    nodes_[n] = {node.centroid, node.parent, node.isCluster()};
  }
  const int elements = static_cast<int>(solver.solution().size());
  leafOf_.resize(elements);
  scale_.resize(elements);
  for (int e = 0; e < elements; ++e) {
    leafOf_[e] = tree.leafOf(e);
    scale_[e] = solver.ancestorScale(e);
  }
  gather_.resize(links_.size());
  for (int r : links_.receivers())
    for (int64_t k = links_.begin(r); k < links_.end(r); ++k) {
      const Rgb g = solver.linkGather(r, k);
      gather_[k] = Eigen::Vector3f(static_cast<float>(g.r), static_cast<float>(g.g),
                                   static_cast<float>(g.b));
    }
}

std::vector<ElementLink> ElementLinks::of(int element) const {
  RAD_CHECK(element >= 0 && element < elementCount());
  std::vector<ElementLink> out;
  bool aboveDeepest = false;  // past the deepest receiver: the element's correction applies
  for (int r = leafOf_[element]; r >= 0; r = nodes_[r].parent) {
    if (!links_.hasLinks(r)) continue;
    const double scale = aboveDeepest ? scale_[element] : 1.0;
    for (int64_t k = links_.begin(r); k < links_.end(r); ++k) {
      const Link& link = links_[k];
      ElementLink l;
      l.receiver = r;
      l.source = link.source;
      l.receiverCentroid = nodes_[r].centroid;
      l.sourceCentroid = nodes_[link.source].centroid;
      l.sourceIsCluster = nodes_[link.source].cluster;
      l.factor = link.factor;
      l.irradiance = Rgb(gather_[k].x(), gather_[k].y(), gather_[k].z()) * scale;
      out.push_back(l);
    }
    aboveDeepest = true;
  }
  return out;
}

}  // namespace rad
