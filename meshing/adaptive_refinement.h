#pragma once

#include <array>
#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

struct RefinementOptions {
  // An element is a candidate for splitting when the radiance shown over it (linear interpolation
  // of the vertex values) departs from the solution by more than threshold × the local radiance
  // (the larger of the element's and its corners' values): see displayedVariation().
  double threshold = 0.1;
  double minArea = 0;   // elements at or below this area are never split
  int maxElements = 0;  // never split beyond this count (0: no limit)
};

// Per element, an estimate of how far the radiance a viewer sees over it (linear interpolation of
// VertexInterpolation's vertex values: area-weighted means of the elements around each corner,
// kept apart at creases and material borders) is from the solution: the larger of (a) the
// displayed mean over the element against its solved value, and (b) at each corner, the displayed
// value against a plane fitted by area-weighted least squares to the values of the elements
// around that corner, evaluated at the corner (gradient recovery, as in Zienkiewicz–Zhu). Zero
// for a linear field; about h·|∇L| at a border or crease, where a corner's mean is one-sided;
// about h²·|∇²L| where the field bends; a fraction of the jump where a shadow edge or a contact
// crosses, however small the element. Same units as `luminance`.
std::vector<double> displayedVariation(const PatchMesh& mesh, const std::vector<double>& luminance);

// Elements worth splitting after a solve, most important first. Candidates are the elements
// whose displayed error (above) exceeds the relative threshold, and those a shadow boundary
// crosses (partlyShadowed[e] != 0; may be empty), counted at the spread of their displayed corner
// values since their mean can hide the jump; errors below 1e-3 of the mean luminance are noise
// and ignored, and elements at or below minArea are left alone. The order is by area × error²,
// an element's share of the area-weighted squared error of what is displayed, so a limited budget
// goes where it removes the most error.
std::vector<int> selectForRefinement(const PatchMesh& mesh, const std::vector<double>& luminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options);

// Per element, from values at its 3 Gauss points (barycentric 2/3, 1/6, 1/6, the point near
// corner k first, in PatchMesh::corners order): how far the radiance displayed over it is from
// them. What is displayed is the linear field of each element through its Gauss points,
// evaluated at its corners, averaged per vertex over the elements around it (as
// VertexInterpolation::interpolateCorners; zero at least), then interpolated linearly; the error
// is the largest gap, at the Gauss points, between that and the element's own values. Zero for
// a linear field, borders and creases included; about h²·|∇²L| where the field bends (the
// elements around a vertex extrapolate to different values), a fraction of the jump where a
// shadow edge or contact crosses. Fills displayedCorners (the displayed corner values) if given.
std::vector<double> displayedPointError(
    const PatchMesh& mesh, const std::vector<std::array<double, 3>>& pointLuminance,
    std::vector<std::array<double, 3>>* displayedCorners = nullptr);

// selectForRefinement from Gauss-point values (displayedPointError as the error, the mean of
// the three as the element's value): what a solve with 3 receiver points refines by.
std::vector<int> selectForRefinement(const PatchMesh& mesh,
                                     const std::vector<std::array<double, 3>>& pointLuminance,
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
