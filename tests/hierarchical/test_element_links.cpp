// The viewer's copy of a solved hierarchy's links (ElementLinks): what it draws for a picked
// element must be the links that element gathers over, no more and no fewer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "radiosity/hierarchical/element_links.h"
#include "tests/support/closed_cube.h"

namespace rad {
namespace {

// A closed cube lit by one of its faces, solved with BF refinement.
struct LitCube {
  PatchMesh mesh = testing::closedCube(0.01);
  RayCaster rays{mesh};
  RadiosityProblem problem;
  std::unique_ptr<HierarchicalRadiosity> hr;
  LitCube() {
    for (int e = 0; e < mesh.elementCount(); ++e) {
      problem.emission.push_back(mesh.patch(e) == 1 ? Rgb(3, 2, 1) : Rgb());
      problem.reflectance.push_back(Rgb(0.7, 0.5, 0.3));
      problem.area.push_back(mesh.area(e));
    }
    HierarchicalOptions options;
    options.raysPerReceiver = 128;
    options.linkEpsilon = 1.0;  // coarse: links to clusters remain
    hr = std::make_unique<HierarchicalRadiosity>(mesh, rays, problem, options);
    for (int pass = 0; pass < 4; ++pass) {
      while (hr->solver().progress() > 1e-6) hr->solver().step();
      if (hr->refineLinks() == 0) break;
    }
    while (hr->solver().progress() > 1e-6) hr->solver().step();
  }
};

// Every element's links are those of the receivers whose leaves hold it (found here by scanning
// every receiver's leaf range), deepest first, with the tree's centroids, the cluster flag and the
// factor.
TEST(ElementLinks, AreTheLinksOfEveryReceiverHoldingTheElement) {
  const LitCube cube;
  const HierarchicalRadiosity& hr = *cube.hr;
  const NodeHierarchy& tree = hr.tree();
  const LinkSet& links = hr.links();
  const ElementLinks kept(hr);
  ASSERT_EQ(kept.elementCount(), cube.mesh.elementCount());
  const std::vector<int> receivers = links.receivers();
  int coarse = 0, clusters = 0;
  for (int e = 0; e < cube.mesh.elementCount(); ++e) {
    const int position = tree.leafPosition(e);
    std::map<std::pair<int, int>, float> expected;
    for (int r : receivers) {
      const HierarchyNode& node = tree.node(r);
      if (node.leafBegin <= position && position < node.leafEnd)
        for (int64_t k = links.begin(r); k < links.end(r); ++k)
          expected[{r, links[k].source}] = links[k].factor;
    }
    const std::vector<ElementLink> got = kept.of(e);
    ASSERT_EQ(got.size(), expected.size()) << "element " << e;
    int lastSpan = 0;
    for (const ElementLink& l : got) {
      const auto it = expected.find({l.receiver, l.source});
      ASSERT_NE(it, expected.end()) << "element " << e << ": a link not gathered by it";
      EXPECT_EQ(l.factor, it->second);
      const HierarchyNode& receiver = tree.node(l.receiver);
      const HierarchyNode& source = tree.node(l.source);
      const int span = receiver.leafEnd - receiver.leafBegin;
      EXPECT_GE(span, lastSpan) << "element " << e << ": receivers not deepest first";
      lastSpan = span;
      EXPECT_EQ(l.receiverCentroid, receiver.centroid);
      EXPECT_EQ(l.sourceCentroid, source.centroid);
      EXPECT_EQ(l.sourceIsCluster, source.isCluster());
      coarse += !receiver.isLeaf();
      clusters += source.isCluster();
    }
  }
  EXPECT_GT(coarse, 0) << "no link held above a leaf: the ancestors were not tested";
  EXPECT_GT(clusters, 0) << "no cluster source: the cluster flag was not tested";
}

// What the links bring, reflected, plus E is the element's B: the viewer's shares are shares of
// the light the element gathers, as the solver gathered it (clusters through their direction
// bins, the links above the deepest receiver scaled by the element's correction). Exact up to the
// float copy and what the last sweep still changed (tolerance 1e-6). Leaving out the correction
// makes the worst element 36% off (measured).
TEST(ElementLinks, BringTheLightTheElementReflects) {
  const LitCube cube;
  const ElementLinks kept(*cube.hr);
  const std::vector<Rgb>& b = cube.hr->solver().solution();
  double worst = 0;
  for (int e = 0; e < cube.mesh.elementCount(); ++e) {
    Rgb gathered;
    for (const ElementLink& l : kept.of(e)) gathered += l.irradiance;
    const Rgb fromLinks = cube.problem.emission[e] + cube.problem.reflectance[e] * gathered;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(fromLinks[c] / b[e][c] - 1));
  }
  EXPECT_LT(worst, 1e-4);
}

}  // namespace
}  // namespace rad
