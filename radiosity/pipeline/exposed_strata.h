#pragma once

#include "meshing/patch_mesh.h"
#include "radiosity/core/rng.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/visibility/element_exposure.h"

namespace rad {

// An element's mean of what arrives at it (the lights' E_d, the emitters' D) is taken at
// kAreaStrata² points, one jittered in each stratum of the unit square (s, t), which
// uniformPointOnTriangle maps onto the triangle preserving area: equal areas of the element.
constexpr int kAreaStrata = 4;

// Calls visit(x, stratum) at each of those points of element e that is not buried (`exposure`
// may be null: nothing buried), drawing s and t from `jitter` in stratum order; returns how many
// points it visited.
template <class Visit>
int forEachExposedStratum(const PatchMesh& mesh, const ElementExposure* exposure, int e,
                          Rng& jitter, Visit&& visit) {
  const auto corners = mesh.corners(e);
  const bool partlyBuried = exposure != nullptr && exposure->buriedCells(e) != 0;
  int used = 0;
  for (int j = 0; j < kAreaStrata * kAreaStrata; ++j) {
    const double s = (j % kAreaStrata + jitter.uniform()) / kAreaStrata;
    const double t = (j / kAreaStrata + jitter.uniform()) / kAreaStrata;
    if (partlyBuried && exposure->buried(e, s, t)) continue;
    visit(uniformPointOnTriangle(corners, s, t), j);
    ++used;
  }
  return used;
}

}  // namespace rad
