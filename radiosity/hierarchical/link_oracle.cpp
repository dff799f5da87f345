#include "radiosity/hierarchical/link_oracle.h"

#include <algorithm>
#include <cmath>

namespace rad {
namespace {

// Whether every corner of the box lies on or behind the plane through `point` with `normal` (to a
// small fraction of the box's size: coplanar neighbours exchange nothing either).
bool whollyBehind(const HierarchyNode& box, const Eigen::Vector3f& point,
                  const Eigen::Vector3f& normal, float slack) {
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3f p((corner & 1) ? box.boundsMax.x() : box.boundsMin.x(),
                            (corner & 2) ? box.boundsMax.y() : box.boundsMin.y(),
                            (corner & 4) ? box.boundsMax.z() : box.boundsMin.z());
    if (normal.dot(p - point) > slack) return false;
  }
  return true;
}

}  // namespace

LinkOracle::Exchange LinkOracle::estimate(int receiver, int source, double& power) const {
  power = 0;
  const HierarchyNode& r = tree_.node(receiver);
  const HierarchyNode& s = tree_.node(source);
  if (!s.isCluster() && s.patch == r.patch) return Exchange::None;
  if (reflectance_[receiver] <= 0 || r.area <= 0 || s.area <= 0) return Exchange::None;
  const float rr = r.radius(), rs = s.radius();
  const float slack = 1e-5f * (rr + rs);
  if (whollyBehind(s, r.centroid, r.normal, slack)) return Exchange::None;
  if (!s.isCluster() && whollyBehind(r, s.centroid, s.normal, slack)) return Exchange::None;
  const double light = static_cast<double>(reflectance_[receiver]) * radiosity_[source] * r.area;
  const Eigen::Vector3f between = s.centroid - r.centroid;
  const double d = between.norm();
  // Nodes whose bounding spheres overlap: the cosines at the centroids say nothing, so they count
  // as 1 (the disc estimate alone is about right for neighbours: 0.24 for two squares meeting at
  // an edge, whose exact factor is 0.20).
  const bool near = d <= rr + rs;
  const Eigen::Vector3f w =
      d > 0 ? Eigen::Vector3f(between / static_cast<float>(d)) : Eigen::Vector3f::Zero();
  const double cosR =
      near ? 1.0 : std::min(1.0, std::max(0.0, static_cast<double>(r.normal.dot(w))) + rs / d);
  const double cosS =
      near || s.isCluster()
          ? 1.0
          : std::min(1.0, std::max(0.0, static_cast<double>(-s.normal.dot(w))) + rr / d);
  // A cluster shows the receiver at most its bounding sphere's cross-section, however much
  // surface it holds (a field of boxes hides most of its own faces).
  const double shown = s.isCluster() ? std::min<double>(s.area, M_PI * rs * rs) : s.area;
  const double f = shown * cosR * cosS / (M_PI * d * d + shown);
  // Fewer than one of the receiver's rays would reach it: splitting it could not be resolved.
  if (f * rays_ < 1) return Exchange::Unresolved;
  power = light * std::min(1.0, f);
  return Exchange::Estimated;
}

bool LinkOracle::passes(int receiver, int source) const {
  if (tree_.node(receiver).isLeaf() && tree_.node(source).isLeaf()) return true;
  double power = 0;
  return estimate(receiver, source, power) == Exchange::Unresolved ||
         power <= thresholdFor(receiver);
}

void LinkOracle::link(int receiver, int source, std::vector<NodePair>& out) const {
  double power = 0;
  const Exchange exchange = estimate(receiver, source, power);
  if (exchange == Exchange::None) return;
  const HierarchyNode& r = tree_.node(receiver);
  const HierarchyNode& s = tree_.node(source);
  if (exchange == Exchange::Unresolved || power <= thresholdFor(receiver) ||
      (r.isLeaf() && s.isLeaf())) {
    out.emplace_back(receiver, source);
    return;
  }
  // Split the larger node; a receiver is only ever split within its patch.
  const bool splitSource = !s.isLeaf() && (r.isLeaf() || s.radius() >= r.radius());
  if (splitSource) {
    link(receiver, s.child[0], out);
    link(receiver, s.child[1], out);
  } else {
    link(r.child[0], source, out);
    link(r.child[1], source, out);
  }
}

}  // namespace rad
