#pragma once

#include <Eigen/Core>
#include <vector>

#include "radiosity/core/rgb.h"
#include "radiosity/hierarchical/hierarchical_radiosity.h"

namespace rad {

// One link an element gathers over: held by the element's leaf or one of its ancestors (the
// receiver), from a source node (a surface node, a leaf or a cluster).
struct ElementLink {
  int receiver = -1, source = -1;  // nodes of the tree
  Eigen::Vector3f receiverCentroid, sourceCentroid;
  bool sourceIsCluster = false;
  float factor = 0;  // F from the receiver to the source's leaves
  // What it brings the element before ρ (W/m²), as the solver's last sweep gathered it: F · the
  // source's B (a cluster's towards the receiver), times the element's correction on links held
  // above its deepest receiver. ρ · their sum + E is the element's B.
  Rgb irradiance;
};

// What the links of a solved hierarchy bring each element, kept apart from the solve (a copy of
// the tree's centroids and parents, the links with what each gathers, and each element's
// correction) so the viewer can show a picked element's links after the solver, its mesh and its
// problem are gone. About 30 bytes a link and 24 a node: made for the viewer only.
class ElementLinks {
 public:
  explicit ElementLinks(const HierarchicalRadiosity& solved);

  int elementCount() const { return static_cast<int>(leafOf_.size()); }
  // The element's links, deepest receiver first (its leaf, then each ancestor up to the root),
  // each receiver's links in its sources' leaf order.
  std::vector<ElementLink> of(int element) const;

 private:
  struct Node {
    Eigen::Vector3f centroid;
    int parent = -1;
    bool cluster = false;
  };
  std::vector<Node> nodes_;
  std::vector<int> leafOf_;   // per element
  std::vector<float> scale_;  // per element: HierarchicalSolver::ancestorScale
  LinkSet links_;
  std::vector<Eigen::Vector3f> gather_;  // per link: HierarchicalSolver::linkGather
};

}  // namespace rad
