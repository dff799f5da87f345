#include "meshing/adaptive_refinement.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "meshing/vertex_interpolation.h"

namespace rad {
namespace {

// Per element, the values displayed at its corners (VertexInterpolation's area-weighted means of
// the luminance) and the value the solution suggests there: a plane fitted, weighted by area, to
// the centroid values of the elements around the corner, evaluated at the corner. The two agree
// where the field is linear and the vertex sits in the middle of its elements; they differ by
// about h·|∇L| at a border or a crease (the mean is one-sided there) and where the field bends.
struct Corners {
  std::vector<std::array<double, 3>> displayed, recovered;
};

Corners cornerValues(const PatchMesh& mesh, const std::vector<double>& luminance) {
  const VertexInterpolation interpolation(mesh);
  std::vector<Eigen::Vector3d> perElement(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) perElement[e] = Eigen::Vector3d(luminance[e], 0, 0);
  const std::vector<Eigen::Vector3d> atVertices = interpolation.interpolate(perElement);
  std::vector<double> recovered(interpolation.vertexCount());
  for (int v = 0; v < interpolation.vertexCount(); ++v) {
    recovered[v] = atVertices[v].x();
    const Eigen::Vector3d n = interpolation.normal(v);
    const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (int f : interpolation.elementsAround(v)) {
      const Eigen::Vector3d d = mesh.centroid(f) - interpolation.position(v);
      const Eigen::Vector3d basis(1, d.dot(t1), d.dot(t2));
      normal += mesh.area(f) * basis * basis.transpose();
      rhs += mesh.area(f) * luminance[f] * basis;
    }
    // A plane needs centroids that span both directions about their mean (at least three, not in
    // a line); otherwise keep the mean.
    const double weight = normal(0, 0);
    if (!(weight > 0)) continue;
    const Eigen::Vector2d first = normal.block<2, 1>(1, 0);
    const Eigen::Matrix2d spread = normal.block<2, 2>(1, 1) - first * first.transpose() / weight;
    const Eigen::Vector2d moments =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(spread).eigenvalues();
    if (moments[1] > 0 && moments[0] > 1e-2 * moments[1])
      recovered[v] = normal.ldlt().solve(rhs)[0];
  }
  Corners corners;
  corners.displayed.resize(mesh.elementCount());
  corners.recovered.resize(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    for (int k = 0; k < 3; ++k) {
      const int v = interpolation.triangle(e)[k];
      corners.displayed[e][k] = atVertices[v].x();
      corners.recovered[e][k] = recovered[v];
    }
  return corners;
}

// How far what is displayed over element e is from the solution: the displayed mean against the
// element's value, and the displayed corner values against the recovered ones.
double displayError(const Corners& c, const std::vector<double>& luminance, int e) {
  const auto& shown = c.displayed[e];
  double error = std::fabs((shown[0] + shown[1] + shown[2]) / 3 - luminance[e]);
  for (int k = 0; k < 3; ++k) error = std::max(error, std::fabs(shown[k] - c.recovered[e][k]));
  return error;
}

}  // namespace

std::vector<double> displayedVariation(const PatchMesh& mesh,
                                       const std::vector<double>& luminance) {
  const Corners corners = cornerValues(mesh, luminance);
  std::vector<double> variation(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) variation[e] = displayError(corners, luminance, e);
  return variation;
}

namespace {

// Candidates from each element's solved mean, its displayed corner values and its displayed
// error (see selectForRefinement), most important first.
std::vector<int> selectByError(const PatchMesh& mesh, const std::vector<double>& luminance,
                               const std::vector<std::array<double, 3>>& displayed,
                               const std::vector<double>& defect,
                               const std::vector<char>& partlyShadowed,
                               const RefinementOptions& options) {
  const int n = mesh.elementCount();
  double mean = 0, area = 0;
  for (int e = 0; e < n; ++e) {
    mean += luminance[e] * mesh.area(e);
    area += mesh.area(e);
  }
  mean = area > 0 ? mean / area : 0;
  const double noise = 1e-3 * mean;

  std::vector<int> selected;
  std::vector<double> priority(n, 0.0);
  for (int e = 0; e < n; ++e) {
    if (mesh.area(e) <= options.minArea) continue;
    double local = luminance[e], spread = 0;
    for (double c : displayed[e]) {
      local = std::max(local, c);
      spread = std::max(spread, std::fabs(c - luminance[e]));
    }
    // A shadow edge inside the element is a jump the element's mean hides (the mean can sit
    // between its corners' values): count it at the spread of the displayed values instead.
    const bool shadowEdge = !partlyShadowed.empty() && partlyShadowed[e];
    const double error = shadowEdge ? std::max(defect[e], spread) : defect[e];
    if (error <= noise) continue;
    if (error > options.threshold * local || shadowEdge) {
      selected.push_back(e);
      priority[e] = mesh.area(e) * error * error;
    }
  }
  // Largest share of the displayed error first; ties (equal priority) by index, so the order
  // does not depend on the sort's implementation.
  std::stable_sort(selected.begin(), selected.end(),
                   [&](int a, int b) { return priority[a] > priority[b]; });
  return selected;
}

}  // namespace

std::vector<int> selectForRefinement(const PatchMesh& mesh, const std::vector<double>& luminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options) {
  const Corners corners = cornerValues(mesh, luminance);
  std::vector<double> defect(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) defect[e] = displayError(corners, luminance, e);
  return selectByError(mesh, luminance, corners.displayed, defect, partlyShadowed, options);
}

std::vector<double> displayedPointError(const PatchMesh& mesh,
                                        const std::vector<std::array<double, 3>>& pointLuminance,
                                        std::vector<std::array<double, 3>>* displayedCorners) {
  const int n = mesh.elementCount();
  const VertexInterpolation interpolation(mesh);
  std::vector<std::array<Eigen::Vector3d, 3>> corners(n);
  for (int e = 0; e < n; ++e) {
    std::array<Eigen::Vector3d, 3> g;
    for (int k = 0; k < 3; ++k) g[k] = Eigen::Vector3d(pointLuminance[e][k], 0, 0);
    corners[e] = linearAtCorners(g);
  }
  std::vector<Eigen::Vector3d> atVertices = interpolation.interpolateCorners(corners);
  for (auto& v : atVertices) v = v.cwiseMax(0.0);  // as displayed: no negative light
  std::vector<double> error(n, 0.0);
  if (displayedCorners) displayedCorners->resize(n);
  for (int e = 0; e < n; ++e) {
    std::array<double, 3> d;
    for (int k = 0; k < 3; ++k) d[k] = atVertices[interpolation.triangle(e)[k]].x();
    if (displayedCorners) (*displayedCorners)[e] = d;
    // The displayed plane at the Gauss point near corner k (barycentric 2/3, 1/6, 1/6).
    for (int k = 0; k < 3; ++k) {
      const double shown = (4 * d[k] + d[(k + 1) % 3] + d[(k + 2) % 3]) / 6;
      error[e] = std::max(error[e], std::fabs(shown - pointLuminance[e][k]));
    }
  }
  return error;
}

std::vector<int> selectForRefinement(const PatchMesh& mesh,
                                     const std::vector<std::array<double, 3>>& pointLuminance,
                                     const std::vector<char>& partlyShadowed,
                                     const RefinementOptions& options) {
  std::vector<std::array<double, 3>> displayed;
  const std::vector<double> defect = displayedPointError(mesh, pointLuminance, &displayed);
  std::vector<double> luminance(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e)
    luminance[e] = (pointLuminance[e][0] + pointLuminance[e][1] + pointLuminance[e][2]) / 3;
  return selectByError(mesh, luminance, displayed, defect, partlyShadowed, options);
}

std::vector<int> refineElements(PatchMesh& mesh, const std::vector<int>& selected,
                                const RefinementOptions& options, int targetElements) {
  const int before = mesh.elementCount();
  const int limit =
      options.maxElements > 0 ? std::min(targetElements, options.maxElements) : targetElements;
  // Corners and areas of every element before, to find the ones a split changed.
  std::vector<std::array<int, 3>> corners(before);
  std::vector<double> areaBefore(before);
  for (int e = 0; e < before; ++e) {
    corners[e] = mesh.cornerVertices(e);
    areaBefore[e] = mesh.area(e);
  }
  for (int e : selected) {
    if (mesh.elementCount() >= limit) break;
    // A split propagating from an earlier one (Rivara's path) may already have halved e: that
    // already is the refinement e asked for.
    if (mesh.area(e) > options.minArea && mesh.area(e) > 0.75 * areaBefore[e]) mesh.bisect(e);
  }
  std::vector<int> changed;
  for (int e = 0; e < mesh.elementCount(); ++e)
    if (e >= before || mesh.cornerVertices(e) != corners[e]) changed.push_back(e);
  return changed;
}

int refinementTarget(int start, int budget, int pass, int passes) {
  if (passes <= 0 || budget <= start) return std::max(start, budget);
  const double fraction = std::min(1.0, static_cast<double>(pass + 1) / passes);
  return static_cast<int>(
      std::lround(start * std::pow(static_cast<double>(budget) / start, fraction)));
}

}  // namespace rad
