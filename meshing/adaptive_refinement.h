#pragma once

#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

struct RefinementOptions {
  // An element is a candidate for splitting when the radiance shown over it (linear interpolation
  // of the vertex values) departs from its solved value by more than threshold × the local
  // radiance (the larger of the element's and its corners' values).
  double threshold = 0.1;
  double minArea = 0;    // elements at or below this area are never split
  int maxElements = 0;   // never split beyond this count (0: no limit)
};

// Per element, how far the radiance a viewer sees over it departs from the solution: the largest
// difference between the element's own value and the interpolated values at its corners
// (VertexInterpolation: area-weighted means of the elements around each corner, kept apart at
// creases and material borders). Zero where the solution is constant; about h·|∇L| on a smooth
// gradient of an element of size h; about half the jump where a shadow edge or a contact crosses
// the element, however small the element. Same units as `luminance`.
std::vector<double> displayedVariation(const PatchMesh& mesh, const std::vector<double>& luminance);

// Elements worth splitting after a solve, most important first. Candidates are the elements
// whose displayed variation exceeds the relative threshold, and those a shadow boundary crosses
// (partlyShadowed[e] != 0; may be empty); variations below 1e-3 of the mean luminance are noise
// and ignored, and elements at or below minArea are left alone. The order is by area × variation²,
// an element's share of the area-weighted squared error of what is displayed, so a limited budget
// goes where it removes the most error.
std::vector<int> selectForRefinement(const PatchMesh& mesh, const std::vector<double>& luminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options);

// Bisects the selected elements in order (longest edge, conforming) until the mesh holds
// `targetElements` (and never more than options.maxElements when that is set). An element already
// halved by a neighbour's split is not split again in the same call. Returns every element whose
// geometry changed or that is new: the ones a solver must recompute.
std::vector<int> refineElements(PatchMesh& mesh, const std::vector<int>& selected,
                                const RefinementOptions& options, int targetElements);

// Element count to reach after refinement pass `pass` (0-based) of `passes`, growing
// geometrically from `start` to `budget`, so each pass refines on a solution that already
// reflects the previous splits and the budget is spent over all passes.
int refinementTarget(int start, int budget, int pass, int passes);

}  // namespace rad
