#pragma once

#include <string>

#include "radiosity/pipeline/solve_options.h"

namespace rad {

// Which rule set the element size: the user's --max-area, --element-size or --elements, or the
// default derived from the scene. Named in the log and in summary.json.
enum class ElementSizeRule { MaxArea, ElementSize, Elements, SceneDefault };
std::string elementSizeRuleName(ElementSizeRule rule);  // "max-area", …, "scene"

// The size elements are meshed to. An element size S (scene units) stands for the area of the
// equilateral triangle of edge S, S²·√3/4: elements are bisected until none is larger (they come
// out between half and all of it). --elements N instead splits the largest elements until there
// are N, and S is the edge whose equilateral area is the mean, total area / N; then every element
// above kCountedMaxAreaOverMean times that mean is split too, which binds only where the scene's
// own small triangles took the count (the mesh then has more than N elements).
inline constexpr double kCountedMaxAreaOverMean = 2;

struct ElementSizing {
  ElementSizeRule rule = ElementSizeRule::SceneDefault;
  double edge = 0;      // S
  double maxArea = 0;   // the area bound; 0 with --elements
  int targetCount = 0;  // --elements; 0 otherwise
};

double equilateralArea(double edge);
double equilateralEdge(double area);

// The scene default: S = the scene's bounding-box diagonal / kSceneDivisions (the Cornell box
// gets the 1500-element mesh it always had), made coarser where that would give more than
// kDefaultElementBudget elements (a solve of about a minute on two cores). Only ratios of
// lengths enter, so a scene scaled by any factor gets the same mesh.
inline constexpr double kSceneDivisions = 18;
inline constexpr double kDefaultElementBudget = 60000;
ElementSizing decideElementSize(const SolveOptions& options, double totalArea, double diagonal);

// Slivers: elements with a longest edge / altitude above kMaxAspectRatio are split into
// well-shaped ones (PatchMesh::splitSlivers) down to a longest edge of S / kSliverEdgeFraction;
// narrower strips stay thin but no longer than that. With S itself, Sponza's 66 453 triangles
// (50 019 of them slivers) become 82 329 elements; S / 4 would give 179 525.
inline constexpr double kMaxAspectRatio = 4;
inline constexpr double kSliverEdgeFraction = 1;

}  // namespace rad
