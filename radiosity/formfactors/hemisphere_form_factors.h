#pragma once

#include <cstdint>

#include "meshing/patch_mesh.h"
#include "radiosity/formfactors/form_factor_row.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

struct HemisphereOptions {
  int raysPerElement = 1024;
  uint64_t seed = 1;
  // Optional per-element multiplier of raysPerElement (empty: 1 everywhere). Used to give the
  // rows of emitters, which carry all the direct light, as many rays as they need.
  std::vector<int> rayMultiplier = {};
};

// Form factors by cosine-weighted hemisphere ray casting (Monte Carlo "gathering" estimate):
// rays leave uniformly distributed points on element i with cosine-weighted directions, and
// F_ij = (rays whose first hit is the front of j) / (rays cast). Origins and directions are
// stratified (a jittered grid over directions, paired with a shuffled jittered grid over the
// element) to lower the variance without bias.
//
// Each row draws from its own random stream keyed by (seed, element), so a row is the same
// whether it is computed alone (lazily, for shooting) or with all others, on any thread count.
class HemisphereFormFactors {
 public:
  HemisphereFormFactors(const PatchMesh& mesh, const RayCaster& rays, HemisphereOptions options);

  FormFactorRow computeRow(int element) const;  // uses TBB across the row's rays
  int raysForRow(int element) const {
    return options_.rayMultiplier.empty() ? options_.raysPerElement
                                          : options_.raysPerElement * options_.rayMultiplier[element];
  }
  const PatchMesh& mesh() const { return mesh_; }

 private:
  const PatchMesh& mesh_;
  const RayCaster& rays_;
  HemisphereOptions options_;
  std::vector<Eigen::Vector3d> normals_;  // per element, looked up once per ray hit
};

}  // namespace rad
