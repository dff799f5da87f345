#pragma once

#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

struct RefinementOptions {
  double threshold = 0.1;   // relative difference of luminance between neighbours that splits
  double minArea = 0;       // elements at or below this area are never split
  int maxElements = 0;      // stop splitting at this count (0: no limit)
};

// Elements to split after a solve, where the solution is not smooth: an element whose luminance
// differs from that of a neighbour across an edge (same material, surfaces meeting at less than
// 30°) by more than threshold × the larger of the two, or that a shadow boundary crosses
// (partlyShadowed[e] != 0; may be empty). Differences below 1e-3 of the mean luminance are
// ignored, so the dark corners of a scene are not refined for noise.
std::vector<int> selectForRefinement(const PatchMesh& mesh, const std::vector<double>& luminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options);

// Bisects the selected elements (longest edge, conforming) while the budget allows. Returns every
// element whose geometry changed or that is new: the ones a solver must recompute.
std::vector<int> refineElements(PatchMesh& mesh, const std::vector<int>& selected,
                                const RefinementOptions& options);

}  // namespace rad
