#pragma once

#include <cstdint>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/hierarchical/link_set.h"
#include "radiosity/hierarchical/node_hierarchy.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

// The form factors on the links, by cosine-weighted hemisphere rays from the receiver node
// (Monte Carlo, as the hemisphere rows): each receiver casts `rays` rays from points spread over
// its leaves by area (stratified), with cosine-weighted directions about each leaf's normal, and
// F of a link = (rays whose first hit is the front of an element under the link's source) /
// (rays cast from the receiver's exposed parts). So F is the receiver's area average of the
// point form factor to the source's elements, with visibility, whatever the source: a surface,
// or a cluster of surfaces facing every way (no isotropic approximation). Rays that reach sources
// linked to the receiver's ancestors are counted too, as its aboveFraction (HierarchicalSolver's
// correction); those reaching sources linked below it count nowhere here.
//
// Each receiver draws from its own random stream keyed by (seed, node), so its factors do not
// depend on the thread count, and casting a receiver again gives the same rays.
class LinkFormFactors {
 public:
  LinkFormFactors(const NodeHierarchy& tree, const PatchMesh& mesh, const RayCaster& rays,
                  int raysPerReceiver, uint64_t seed, const ElementExposure* exposure);

  // Sets the factors of the links of `receivers` (in parallel). Returns the rays cast.
  uint64_t compute(LinkSet& links, const std::vector<int>& receivers) const;

 private:
  uint64_t computeReceiver(LinkSet& links, int receiver) const;

  const NodeHierarchy& tree_;
  const PatchMesh& mesh_;
  const RayCaster& rays_;
  int raysPerReceiver_;
  uint64_t seed_;
  const ElementExposure* exposure_;
  std::vector<double> areaBefore_;  // per leaf position, the leaves' area before it (and total)
  std::vector<float> normals_;      // x, y, z per element, as Embree's floats
};

}  // namespace rad
