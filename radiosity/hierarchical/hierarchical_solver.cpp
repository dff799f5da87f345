#include "radiosity/hierarchical/hierarchical_solver.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {

HierarchicalSolver::HierarchicalSolver(const NodeHierarchy& tree, const LinkSet& links,
                                       const RadiosityProblem& problem)
    : tree_(tree), links_(links), problem_(problem), clusters_(tree) {
  nodeB_.assign(tree.size(), Rgb());
  scale_.assign(problem.size(), 1.0f);
  for (int root : tree.patchRoots()) normalise(root, 0, 0, 0);
  solution_ = problem.emission;  // B_0 = E
  for (int e = 0; e < problem.size(); ++e) nodeB_[tree.leafOf(e)] = solution_[e];
  pullClusters();
  updateResidual();
}

// Every inner node's B from its children's, deepest first (a child's index is above its parent's).
void HierarchicalSolver::pullClusters() {
  for (int n = tree_.size() - 1; n >= 0; --n) {
    const HierarchyNode& node = tree_.node(n);
    if (node.isLeaf()) continue;
    const HierarchyNode& a = tree_.node(node.child[0]);
    const HierarchyNode& b = tree_.node(node.child[1]);
    nodeB_[n] = node.area > 0
                    ? (nodeB_[node.child[0]] * a.area + nodeB_[node.child[1]] * b.area) / node.area
                    : Rgb();
  }
  clusters_.pull(nodeB_);
}

void HierarchicalSolver::normalise(int n, double factorsAbove, float foreign, float above) {
  double factors = factorsAbove;
  if (links_.hasLinks(n)) {
    double own = 0;
    for (int64_t k = links_.begin(n); k < links_.end(n); ++k) own += links_[k].factor;
    // This receiver's rays that reached its ancestors' sources, whose factors (summing to
    // `factorsAbove`) came from the ancestors' own rays.
    foreign = links_.aboveFraction(n);
    above = static_cast<float>(factorsAbove);
    factors += own;
  }
  const HierarchyNode& node = tree_.node(n);
  if (node.isLeaf()) {
    const int e = tree_.element(n);
    scale_[e] = above > 0 ? foreign / above : 1.0f;
    return;
  }
  normalise(node.child[0], factors, foreign, above);
  normalise(node.child[1], factors, foreign, above);
}

Rgb HierarchicalSolver::radianceSeen(int receiver, int s) const {
  const HierarchyNode& source = tree_.node(s);
  if (!source.isCluster()) return nodeB_[s];
  const Eigen::Vector3f& at = tree_.node(receiver).centroid;
  const Eigen::Vector3f towards = at - source.centroid;
  const float length = towards.norm();
  // A receiver inside the cluster's bounds sees it from every side: its area average.
  if (length > 0 && !((at.array() >= source.boundsMin.array()).all() &&
                      (at.array() <= source.boundsMax.array()).all()))
    return clusters_.towards(s, towards / length);
  return nodeB_[s];
}

Rgb HierarchicalSolver::linkGather(int receiver, int64_t k) const {
  const Link& link = links_[k];
  if (link.factor <= 0) return Rgb();
  if (tree_.node(link.source).isLeaf())
    return nodeB_[link.source] * static_cast<double>(link.factor);
  // The source's parts weighted by the link's hits in each (Link::seen).
  Rgb sum;
  int weight = 0;
  for (int part = 0; part < Link::kSeenParts; ++part) {
    if (link.seen[part] == 0) continue;
    sum += radianceSeen(receiver, seenPartNode(tree_, link.source, part)) * link.seen[part];
    weight += link.seen[part];
  }
  return weight > 0 ? sum * (static_cast<double>(link.factor) / weight) : Rgb();
}

Rgb HierarchicalSolver::gathered(int node) const {
  Rgb sum;
  for (int64_t k = links_.begin(node); k < links_.end(node); ++k) sum += linkGather(node, k);
  return sum;
}

Rgb HierarchicalSolver::pushPull(int n, const Rgb& above, const Rgb& aboveDeepest) {
  const HierarchyNode& node = tree_.node(n);
  const Rgb own = gathered(n);
  const Rgb arriving = above + own;
  const Rgb deepest = links_.hasLinks(n) ? above : aboveDeepest;
  if (node.isLeaf()) {
    const int e = tree_.element(n);
    const Rgb b =
        problem_.emission[e] + problem_.reflectance[e] * (arriving + deepest * (scale_[e] - 1.0));
    solution_[e] = b;
    nodeB_[n] = b;
    return b * node.area;
  }
  const Rgb power =
      pushPull(node.child[0], arriving, deepest) + pushPull(node.child[1], arriving, deepest);
  nodeB_[n] = node.area > 0 ? power / node.area : Rgb();
  return power;
}

void HierarchicalSolver::step() {
  for (int root : tree_.patchRoots()) {
    const Rgb before = nodeB_[root];
    pushPull(root, Rgb(), Rgb());
    const double area = tree_.node(root).area;
    if (area <= 0) continue;
    const Rgb change = (nodeB_[root] - before) * area;
    for (int a = tree_.node(root).parent; a >= 0; a = tree_.node(a).parent)
      if (tree_.node(a).area > 0) nodeB_[a] += change / tree_.node(a).area;
    clusters_.addChange(root, nodeB_[root] - before);
  }
  pullClusters();  // exact averages again, without the increments' rounding
  ++iterations_;
  updateResidual();
}

void HierarchicalSolver::continueFrom(const HierarchicalSolver& other) {
  RAD_CHECK(&other.tree_ == &tree_);
  nodeB_ = other.nodeB_;
  solution_ = other.solution_;
  iterations_ = other.iterations_;
  clusters_.pull(nodeB_);
  updateResidual();
}

void HierarchicalSolver::updateResidual() {
  const double power = problem_.emittedPower();
  residual_ = power > 0 ? residualNorm() / power : 0;
}

void HierarchicalSolver::residualOf(int n, const Rgb& above, const Rgb& aboveDeepest,
                                    double& sum) const {
  const HierarchyNode& node = tree_.node(n);
  const Rgb arriving = above + gathered(n);
  const Rgb deepest = links_.hasLinks(n) ? above : aboveDeepest;
  if (node.isLeaf()) {
    const int e = tree_.element(n);
    const Rgb r = problem_.emission[e] +
                  problem_.reflectance[e] * (arriving + deepest * (scale_[e] - 1.0)) - solution_[e];
    sum += node.area * (std::abs(r.r) + std::abs(r.g) + std::abs(r.b));
    return;
  }
  residualOf(node.child[0], arriving, deepest, sum);
  residualOf(node.child[1], arriving, deepest, sum);
}

double HierarchicalSolver::residualNorm() const {
  // Per patch in parallel, then summed in order: the same value on any thread count.
  const std::vector<int>& roots = tree_.patchRoots();
  std::vector<double> perPatch(roots.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, roots.size(), 64),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k < range.end(); ++k)
                        residualOf(roots[k], Rgb(), Rgb(), perPatch[k]);
                    });
  double sum = 0;
  for (double v : perPatch) sum += v;
  return sum;
}

}  // namespace rad
