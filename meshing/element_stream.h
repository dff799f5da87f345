#pragma once

#include <cstdint>
#include <cstring>

#include "meshing/patch_mesh.h"
#include "radiosity/core/rng.h"

namespace rad {

// The key of an element's random streams: its material and the exact bits of its corners, not
// its index. Every per-element stream of a solve (its form-factor rays, its direct light's strata
// and shadow rays, the emitters' first shot at it) is drawn under this key, so an element an edit
// leaves in place draws the same rays whatever the edit renumbers: `radiosity update` then equals
// a fresh solve of the edited scene row for row. (Two elements with the same material and corners,
// a duplicated face, share their streams: correlated, each still unbiased.)
inline uint64_t elementStream(const PatchMesh& mesh, int element) {
  uint64_t key = mix64(static_cast<uint64_t>(static_cast<uint32_t>(mesh.material(element))));
  for (const Eigen::Vector3d& corner : mesh.corners(element))
    for (int d = 0; d < 3; ++d) {
      uint64_t bits;
      std::memcpy(&bits, &corner[d], sizeof bits);
      key = mix64(key ^ bits);
    }
  return key;
}

}  // namespace rad
