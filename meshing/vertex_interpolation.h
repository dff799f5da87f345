#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "meshing/patch_mesh.h"

namespace rad {

// Per-vertex values for baked vertex colours. A mesh vertex is split into several output
// vertices where the elements around it differ in material or bend by more than the crease
// angle, so a room's corners and the border between two materials stay sharp instead of
// bleeding into each other. Each output vertex holds the area-weighted mean of its elements.
class VertexInterpolation {
 public:
  explicit VertexInterpolation(const PatchMesh& mesh, double creaseAngleDegrees = 30.0);
  // Weighted by `elementWeights` (one per element) instead of the areas: the exposed areas, so an
  // element buried under a box (B of a part no light reaches) does not darken its neighbours'
  // vertices. A vertex whose elements all weigh 0 takes their area-weighted mean.
  VertexInterpolation(const PatchMesh& mesh, const std::vector<double>& elementWeights,
                      double creaseAngleDegrees = 30.0);

  int vertexCount() const { return static_cast<int>(positions_.size()); }
  const Eigen::Vector3d& position(int vertex) const { return positions_[vertex]; }
  const Eigen::Vector3d& normal(int vertex) const { return normals_[vertex]; }
  // Output-vertex indices of an element's corners, in the element's winding.
  const std::array<int, 3>& triangle(int element) const { return triangles_[element]; }

  std::vector<Eigen::Vector3d> interpolate(const std::vector<Eigen::Vector3d>& perElement) const;
  // The same from a value per element corner (perElementCorners[e][k] at corner k of
  // triangle(e)): each output vertex takes the area-weighted mean of what its elements give at
  // it. With corners of a field linear over each element (linearAtCorners), a vertex at a border
  // or crease is extrapolated from its own side instead of averaged over it, so it is exact for
  // a linear field there too.
  std::vector<Eigen::Vector3d> interpolateCorners(
      const std::vector<std::array<Eigen::Vector3d, 3>>& perElementCorners) const;

  // The elements whose means make up output vertex v's value.
  std::vector<int> elementsAround(int vertex) const {
    return {elements_.begin() + offsets_[vertex], elements_.begin() + offsets_[vertex + 1]};
  }

 private:
  std::vector<Eigen::Vector3d> positions_, normals_;
  std::vector<std::array<int, 3>> triangles_;
  // For output vertex v, its elements are elements_[offsets_[v] .. offsets_[v+1]).
  std::vector<int> offsets_, elements_;
  std::vector<double> weights_;
};

// The corner values of the linear function through values at a triangle's degree-2 Gauss points
// (barycentric 2/3, 1/6, 1/6, the point near corner k first): 2·g_k − (g_0 + g_1 + g_2)/3.
template <class Value>
std::array<Value, 3> linearAtCorners(const std::array<Value, 3>& atGaussPoints) {
  const Value mean = (atGaussPoints[0] + atGaussPoints[1] + atGaussPoints[2]) / 3.0;
  return {2.0 * atGaussPoints[0] - mean, 2.0 * atGaussPoints[1] - mean,
          2.0 * atGaussPoints[2] - mean};
}

}  // namespace rad
