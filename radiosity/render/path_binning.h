#pragma once

#include <string>
#include <string_view>

#include "radiosity/render/path_expression.h"

namespace rad {

// Sorts the contributions of a path integrator into images by each light path's Heckbert label,
// written light to eye ("LDSE"): every contribution carries one full path, so its label is
// definite even when strategies are combined by multiple importance sampling.
class PathBinning {
 public:
  virtual ~PathBinning() = default;
  virtual int binCount() const = 0;
  // The image the contribution of a path with this label goes to; -1: none.
  virtual int binOf(std::string_view label) const = 0;
};

// `--paths EXPR`: one image, of the paths the expression matches.
class ExpressionBinning : public PathBinning {
 public:
  explicit ExpressionBinning(PathExpression expression) : expression_(std::move(expression)) {}
  int binCount() const override { return 1; }
  int binOf(std::string_view label) const override { return expression_.matches(label) ? 0 : -1; }

 private:
  PathExpression expression_;
};

// `--bounces-separate K`: image k holds the Neumann term T^k L_e, the paths with exactly k
// scattering vertices (D or S: one application of the transport operator per surface
// interaction) between the emitter and the eye; paths with more than K go to no image.
class BounceBinning : public PathBinning {
 public:
  explicit BounceBinning(int maxBounces) : maxBounces_(maxBounces) {}
  int binCount() const override { return maxBounces_ + 1; }
  int binOf(std::string_view label) const override {
    const int k = static_cast<int>(label.size()) - 2;  // all but L and E
    return k <= maxBounces_ ? k : -1;
  }

 private:
  int maxBounces_;
};

}  // namespace rad
