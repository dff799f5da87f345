#include "radiosity/hierarchical/hierarchical_radiosity.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// Per node, B summed over the channels: what the oracle weighs a source by.
std::vector<float> channelSums(const std::vector<Rgb>& nodeB) {
  std::vector<float> out(nodeB.size());
  for (size_t n = 0; n < nodeB.size(); ++n)
    out[n] = static_cast<float>(nodeB[n].r + nodeB[n].g + nodeB[n].b);
  return out;
}

// Per node, the largest channel of ρ over its leaves: a receiver reflects at most this.
std::vector<float> largestReflectance(const NodeHierarchy& tree, const RadiosityProblem& problem) {
  std::vector<float> out(tree.size(), 0.0f);
  for (int n = tree.size() - 1; n >= 0; --n) {  // children after their parents
    const HierarchyNode& node = tree.node(n);
    out[n] = node.isLeaf() ? static_cast<float>(problem.reflectance[tree.element(n)].maxComponent())
                           : std::max(out[node.child[0]], out[node.child[1]]);
  }
  return out;
}

// Per node, the area average of per-element values.
std::vector<Rgb> nodeAverages(const NodeHierarchy& tree, const std::vector<Rgb>& perElement) {
  std::vector<Rgb> out(tree.size());
  for (int n = tree.size() - 1; n >= 0; --n) {
    const HierarchyNode& node = tree.node(n);
    if (node.isLeaf()) {
      out[n] = perElement[tree.element(n)];
      continue;
    }
    const HierarchyNode& a = tree.node(node.child[0]);
    const HierarchyNode& b = tree.node(node.child[1]);
    out[n] = node.area > 0 ? (out[node.child[0]] * a.area + out[node.child[1]] * b.area) / node.area
                           : Rgb();
  }
  return out;
}

// Runs `linkOne(item, out)` over `work` in parallel; the pairs made, in one list (in no
// particular order: LinkSet sorts them).
template <typename Work, typename LinkOne>
std::vector<NodePair> linkInParallel(const std::vector<Work>& work, const LinkOne& linkOne) {
  tbb::enumerable_thread_specific<std::vector<NodePair>> made;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, work.size(), 16),
                    [&](const tbb::blocked_range<size_t>& range) {
                      std::vector<NodePair>& out = made.local();
                      for (size_t k = range.begin(); k < range.end(); ++k) linkOne(work[k], out);
                    });
  std::vector<NodePair> all;
  for (std::vector<NodePair>& part : made) all.insert(all.end(), part.begin(), part.end());
  return all;
}

double meanArea(const RadiosityProblem& problem) {
  double sum = 0;
  for (double a : problem.area) sum += a;
  return problem.size() > 0 ? sum / problem.size() : 0.0;
}

}  // namespace

HierarchicalRadiosity::HierarchicalRadiosity(const PatchMesh& mesh, const RayCaster& rays,
                                             const RadiosityProblem& problem,
                                             HierarchicalOptions options)
    : problem_(problem),
      tree_(mesh, problem.area),
      reflectance_(largestReflectance(tree_, problem)),
      radiosity_(channelSums(nodeAverages(tree_, problem.emission))),
      oracle_(tree_, radiosity_, reflectance_,
              options.linkEpsilon * problem.emittedPower() / problem.size(),
              options.raysPerReceiver, meanArea(problem)),
      factors_(tree_, mesh, rays, options.raysPerReceiver, options.seed, options.exposure) {
  // Every patch linked to the root and refined from there: clusters keep this O(n log n).
  links_ = std::make_unique<LinkSet>(
      tree_, linkInParallel(tree_.patchRoots(), [&](int root, std::vector<NodePair>& out) {
        oracle_.link(root, tree_.root(), out);
      }));
  raysCast_ += factors_.compute(*links_, links_->receivers());
  solver_ = std::make_unique<HierarchicalSolver>(tree_, *links_, problem_);
}

int64_t HierarchicalRadiosity::refineLinks() {
  radiosity_ = channelSums(solver_->nodeRadiosity());  // the oracle reads it by reference
  const LinkSet& links = *links_;
  const std::vector<int> receivers = links.receivers();
  std::vector<char> failing(static_cast<size_t>(links.size()), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, receivers.size(), 64),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k < range.end(); ++k) {
                        const int r = receivers[k];
                        for (int64_t l = links.begin(r); l < links.end(r); ++l)
                          failing[l] = !oracle_.passes(r, links[l].source);
                      }
                    });
  const int64_t split = std::count(failing.begin(), failing.end(), 1);
  if (split == 0) return 0;

  std::vector<NodePair> kept, failed;
  for (int r : receivers)
    for (int64_t l = links.begin(r); l < links.end(r); ++l)
      (failing[l] ? failed : kept).emplace_back(r, links[l].source);
  const std::vector<NodePair> made = linkInParallel(
      failed,
      [&](const NodePair& p, std::vector<NodePair>& out) { oracle_.link(p.first, p.second, out); });
  std::vector<char> touched(tree_.size(), 0);
  for (const NodePair& p : failed) touched[p.first] = 1;
  for (const NodePair& p : made) touched[p.first] = 1;
  std::vector<int> changed;
  for (int n = 0; n < tree_.size(); ++n)
    if (touched[n]) changed.push_back(n);
  kept.insert(kept.end(), made.begin(), made.end());
  auto next = std::make_unique<LinkSet>(tree_, std::move(kept));

  // The receivers whose links did not change keep them in the same order, and casting them again
  // would give the same rays: their links are copied over.
  for (int r : receivers) {
    if (touched[r]) continue;
    RAD_CHECK(next->end(r) - next->begin(r) == links.end(r) - links.begin(r));
    for (int64_t l = links.begin(r), m = next->begin(r); l < links.end(r); ++l, ++m)
      (*next)[m] = links[l];
    next->setAboveFraction(r, links.aboveFraction(r));
  }
  raysCast_ += factors_.compute(*next, changed);
  auto continued = std::make_unique<HierarchicalSolver>(tree_, *next, problem_);
  continued->continueFrom(*solver_);
  solver_ = std::move(continued);
  links_ = std::move(next);
  ++passes_;
  refined_ += split;
  return split;
}

}  // namespace rad
