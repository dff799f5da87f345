#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace rad {

// One link of a hierarchical solve that a picked element gathers over, for drawing: from the
// centroid of the node that holds it (the element's leaf or an ancestor) to its source's.
struct LinkSegment {
  Eigen::Vector3d from, to;
  bool cluster = false;  // the source is a cluster of patches
  double share = 0;      // of the light the element's links bring (luminance), 0..1
};

// The links an element gathers over; the command line adapts the solve's (the viewer never
// depends on the solvers).
using LinksOfElement = std::function<std::vector<LinkSegment>(int element)>;

}  // namespace rad
