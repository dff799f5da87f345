#include "meshing/vertex_interpolation.h"

#include <cmath>

#include "radiosity/core/check.h"

namespace rad {

VertexInterpolation::VertexInterpolation(const PatchMesh& patchMesh, double creaseAngleDegrees)
    : VertexInterpolation(patchMesh, {}, creaseAngleDegrees) {}

VertexInterpolation::VertexInterpolation(const PatchMesh& patchMesh,
                                         const std::vector<double>& elementWeights,
                                         double creaseAngleDegrees) {
  RAD_CHECK(elementWeights.empty() ||
            elementWeights.size() == static_cast<size_t>(patchMesh.elementCount()));
  const TriMesh& mesh = patchMesh.mesh();
  const double cosCrease = std::cos(creaseAngleDegrees * M_PI / 180.0);
  const int elementCount = patchMesh.elementCount();
  triangles_.assign(elementCount, {-1, -1, -1});
  std::vector<Eigen::Vector3d> elementNormals(elementCount);
  for (int e = 0; e < elementCount; ++e) elementNormals[e] = patchMesh.normal(e);

  struct Cluster {
    int vertex;
    int material;
    Eigen::Vector3d normal;
  };
  std::vector<std::vector<int>> members;  // elements of each output vertex
  offsets_.push_back(0);
  for (auto vh : mesh.vertices()) {
    std::vector<Cluster> clusters;
    for (auto fh : mesh.vf_range(vh)) {
      const int e = fh.idx();
      int chosen = -1;
      for (const Cluster& c : clusters)
        if (c.material == patchMesh.material(e) && c.normal.dot(elementNormals[e]) >= cosCrease) {
          chosen = c.vertex;
          break;
        }
      if (chosen < 0) {
        chosen = static_cast<int>(positions_.size());
        clusters.push_back({chosen, patchMesh.material(e), elementNormals[e]});
        positions_.push_back(patchMesh.position(vh.idx()));
        members.emplace_back();
      }
      members[chosen].push_back(e);
      const auto corners = patchMesh.cornerVertices(e);
      for (int k = 0; k < 3; ++k)
        if (corners[k] == vh.idx()) triangles_[e][k] = chosen;
    }
  }
  normals_.resize(positions_.size());
  for (size_t v = 0; v < members.size(); ++v) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    double given = 0;
    for (int e : members[v]) given += elementWeights.empty() ? 0 : elementWeights[e];
    for (int e : members[v]) {
      elements_.push_back(e);
      weights_.push_back(given > 0 ? elementWeights[e] : patchMesh.area(e));
      n += patchMesh.area(e) * elementNormals[e];
    }
    normals_[v] = n.normalized();
    offsets_.push_back(static_cast<int>(elements_.size()));
  }
  for (const auto& t : triangles_)
    RAD_CHECK_MSG(t[0] >= 0 && t[1] >= 0 && t[2] >= 0,
                  "VertexInterpolation: element corner without an output vertex");
}

std::vector<Eigen::Vector3d> VertexInterpolation::interpolate(
    const std::vector<Eigen::Vector3d>& perElement) const {
  std::vector<Eigen::Vector3d> out(positions_.size(), Eigen::Vector3d::Zero());
  for (size_t v = 0; v < positions_.size(); ++v) {
    double weightSum = 0;
    for (int k = offsets_[v]; k < offsets_[v + 1]; ++k) {
      out[v] += weights_[k] * perElement[elements_[k]];
      weightSum += weights_[k];
    }
    if (weightSum > 0) out[v] /= weightSum;
  }
  return out;
}

std::vector<Eigen::Vector3d> VertexInterpolation::interpolateCorners(
    const std::vector<std::array<Eigen::Vector3d, 3>>& perElementCorners) const {
  // Each element's weight at its corner k, found by its position in the triangle.
  std::vector<Eigen::Vector3d> out(positions_.size(), Eigen::Vector3d::Zero());
  for (size_t v = 0; v < positions_.size(); ++v) {
    double weightSum = 0;
    for (int k = offsets_[v]; k < offsets_[v + 1]; ++k) {
      const int e = elements_[k];
      const auto& t = triangles_[e];
      const int corner = t[0] == static_cast<int>(v) ? 0 : (t[1] == static_cast<int>(v) ? 1 : 2);
      out[v] += weights_[k] * perElementCorners[e][corner];
      weightSum += weights_[k];
    }
    if (weightSum > 0) out[v] /= weightSum;
  }
  return out;
}

}  // namespace rad
