#include "radiosity/hierarchical/link_form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>

#include "radiosity/core/rng.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/formfactors/hemisphere_sampling.h"

namespace rad {

LinkFormFactors::LinkFormFactors(const NodeHierarchy& tree, const PatchMesh& mesh,
                                 const RayCaster& rays, int raysPerReceiver, uint64_t seed,
                                 const ElementExposure* exposure)
    : tree_(tree),
      mesh_(mesh),
      rays_(rays),
      raysPerReceiver_(raysPerReceiver),
      seed_(seed),
      exposure_(exposure) {
  const int elements = mesh.elementCount();
  areaBefore_.assign(static_cast<size_t>(elements) + 1, 0.0);
  for (int pos = 0; pos < elements; ++pos)
    areaBefore_[pos + 1] = areaBefore_[pos] + tree.node(tree.leafOf(tree.elementAt(pos))).area;
  normals_.resize(3 * static_cast<size_t>(elements));
  for (int e = 0; e < elements; ++e) {
    const Eigen::Vector3d n = mesh.normal(e);
    for (int k = 0; k < 3; ++k) normals_[3 * e + k] = static_cast<float>(n[k]);
  }
}

uint64_t LinkFormFactors::compute(LinkSet& links, const std::vector<int>& receivers) const {
  std::atomic<uint64_t> cast{0};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, receivers.size(), 8),
                    [&](const tbb::blocked_range<size_t>& range) {
                      uint64_t local = 0;
                      for (size_t k = range.begin(); k < range.end(); ++k)
                        local += computeReceiver(links, receivers[k]);
                      cast += local;
                    });
  return cast.load();
}

uint64_t LinkFormFactors::computeReceiver(LinkSet& links, int receiver) const {
  const HierarchyNode& r = tree_.node(receiver);
  const int64_t first = links.begin(receiver), last = links.end(receiver);
  for (int64_t k = first; k < last; ++k) {
    links[k].factor = 0;
    links[k].seen = {};
  }
  links.setAboveFraction(receiver, 0);
  const double lo = areaBefore_[r.leafBegin], hi = areaBefore_[r.leafEnd];
  if (first == last || !(hi > lo)) return 0;

  const int n = raysPerReceiver_;
  Rng rng(streamKey(seed_, stream_tag::kHierarchicalLinks, static_cast<uint64_t>(receiver)));
  // Directions: a jittered grid over the unit square, its cells dealt to the rays in a shuffled
  // order, so origins (stratified by area) and directions are stratified independently.
  const int grid = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(n))));
  std::vector<int> cell(n);
  std::iota(cell.begin(), cell.end(), 0);
  for (int k = n - 1; k > 0; --k) std::swap(cell[k], cell[rng.below(static_cast<uint32_t>(k + 1))]);

  std::vector<float> coords(6 * static_cast<size_t>(n));
  float* origin[3] = {&coords[0], &coords[n], &coords[2 * n]};
  float* direction[3] = {&coords[3 * n], &coords[4 * n], &coords[5 * n]};
  const Eigen::Vector3d& centre = rays_.centre();
  int cast = 0;
  int leaf = -1;
  std::array<Eigen::Vector3d, 3> corners;
  corners.fill(Eigen::Vector3d::Zero());  // set at the first origin; zeroed for the compiler
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Frame frame(normal);
  for (int k = 0; k < n; ++k) {
    const double at = lo + (hi - lo) * (k + rng.uniform()) / n;
    const auto it =
        std::upper_bound(areaBefore_.begin() + r.leafBegin, areaBefore_.begin() + r.leafEnd, at);
    const int pos = std::min(r.leafEnd - 1, static_cast<int>(it - areaBefore_.begin()) - 1);
    const int e = tree_.elementAt(std::max(r.leafBegin, pos));
    const double s = rng.uniform(), t = rng.uniform();
    double u1, u2;
    if (cell[k] < grid * grid) {
      u1 = (cell[k] % grid + rng.uniform()) / grid;
      u2 = (cell[k] / grid + rng.uniform()) / grid;
    } else {
      u1 = rng.uniform();
      u2 = rng.uniform();
    }
    if (exposure_ && exposure_->buried(e, s, t)) continue;  // shoots from exposed parts only
    if (e != leaf) {  // origins come in leaf order (stratified along the area): look up once each
      leaf = e;
      corners = mesh_.corners(e);
      normal = mesh_.normal(e);
      frame = Frame(normal);
    }
    const Eigen::Vector3d point =
        rays_.liftOff(uniformPointOnTriangle(corners, s, t), normal, normal) - centre;
    const Eigen::Vector3d dir = frame.toWorld(cosineWeightedDirection(u1, u2));
    for (int a = 0; a < 3; ++a) {
      origin[a][cast] = static_cast<float>(point[a]);
      direction[a][cast] = static_cast<float>(dir[a]);
    }
    ++cast;
  }
  if (cast == 0) return 0;
  std::vector<int> hit(cast);
  std::vector<float> distance(cast);
  rays_.closestHits(cast, origin, direction, hit.data(), distance.data());
  std::vector<int> count(static_cast<size_t>(last - first), 0);
  std::vector<std::array<int, Link::kSeenParts>> seen(static_cast<size_t>(last - first));
  int above = 0;
  for (int k = 0; k < cast; ++k) {
    const int h = hit[k];
    if (h < 0) continue;
    const float* nh = &normals_[3 * static_cast<size_t>(h)];
    if (nh[0] * direction[0][k] + nh[1] * direction[1][k] + nh[2] * direction[2][k] >= 0)
      continue;  // the back of a one-sided element absorbs
    const int pos = tree_.leafPosition(h);
    const int64_t l = links.find(tree_, receiver, pos);
    if (l >= 0) {
      ++count[l - first];
      ++seen[l - first][seenPart(tree_, links[l].source, pos)];
      continue;
    }
    for (int a = r.parent; a >= 0 && !tree_.node(a).isCluster(); a = tree_.node(a).parent)
      if (links.find(tree_, a, pos) >= 0) {
        ++above;
        break;
      }
  }
  for (int64_t k = first; k < last; ++k) {
    const int hits = count[k - first];
    links[k].factor = static_cast<float>(static_cast<double>(hits) / cast);
    for (int part = 0; part < Link::kSeenParts; ++part)
      links[k].seen[part] =
          hits > 0 ? static_cast<uint8_t>(std::lround(255.0 * seen[k - first][part] / hits)) : 0;
  }
  links.setAboveFraction(receiver, static_cast<float>(static_cast<double>(above) / cast));
  return static_cast<uint64_t>(cast);
}

}  // namespace rad
