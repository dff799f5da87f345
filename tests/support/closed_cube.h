#pragma once

#include "meshing/patch_mesh.h"

namespace rad::testing {

// A closed unit cube whose six faces look inward: the furnace enclosure.
inline PatchMesh closedCube(double maxArea) {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  PatchMesh mesh(p, {{{0, 1, 2, 3}, 0},
                     {{4, 7, 6, 5}, 0},
                     {{0, 4, 5, 1}, 0},
                     {{3, 2, 6, 7}, 0},
                     {{0, 3, 7, 4}, 0},
                     {{1, 5, 6, 2}, 0}});
  mesh.subdivideUniform(maxArea);
  return mesh;
}

}  // namespace rad::testing
