#include "radiosity/pipeline/element_size.h"

#include <algorithm>
#include <cmath>

#include "radiosity/core/check.h"

namespace rad {

std::string elementSizeRuleName(ElementSizeRule rule) {
  switch (rule) {
    case ElementSizeRule::MaxArea:
      return "max-area";
    case ElementSizeRule::ElementSize:
      return "element-size";
    case ElementSizeRule::Elements:
      return "elements";
    case ElementSizeRule::SceneDefault:
      break;
  }
  return "scene";
}

double equilateralArea(double edge) { return edge * edge * std::sqrt(3.0) / 4; }
double equilateralEdge(double area) { return std::sqrt(4 * area / std::sqrt(3.0)); }

ElementSizing decideElementSize(const SolveOptions& options, double totalArea, double diagonal) {
  RAD_CHECK_GT(totalArea, 0.0);
  ElementSizing out;
  if (options.maxArea > 0) {
    out.rule = ElementSizeRule::MaxArea;
    out.maxArea = options.maxArea;
    out.edge = equilateralEdge(out.maxArea);
  } else if (options.elementSize > 0) {
    out.rule = ElementSizeRule::ElementSize;
    out.edge = options.elementSize;
    out.maxArea = equilateralArea(out.edge);
  } else if (options.targetElements > 0) {
    out.rule = ElementSizeRule::Elements;
    out.targetCount = options.targetElements;
    out.edge = equilateralEdge(totalArea / options.targetElements);
  } else {
    out.rule = ElementSizeRule::SceneDefault;
    RAD_CHECK_GT(diagonal, 0.0);
    // Bisection to an area bound A gives about 1.4 · totalArea / A elements (between A/2 and A).
    const double fromExtent = diagonal / kSceneDivisions;
    const double fromBudget = equilateralEdge(1.4 * totalArea / kDefaultElementBudget);
    out.edge = std::max(fromExtent, fromBudget);
    out.maxArea = equilateralArea(out.edge);
  }
  return out;
}

}  // namespace rad
