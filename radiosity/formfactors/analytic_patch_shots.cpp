#include "radiosity/formfactors/analytic_patch_shots.h"

#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/core/progress.h"
#include "radiosity/core/rng.h"
#include "radiosity/core/seconds_since.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "radiosity/formfactors/receiver_points.h"

namespace rad {
AnalyticPatchShots::AnalyticPatchShots(const PatchMesh& mesh, const RayCaster& rays,
                                       AnalyticOptions options)
    : mesh_(mesh), rays_(rays), options_(options), rows_(mesh.shooterCount()) {
  RAD_CHECK_MSG(options_.receiverPoints == 1 || options_.receiverPoints == 3,
                "receiver points must be 1 or 3");
  RAD_CHECK_GE(options_.shadowRays, 1);
  meshChanged();
  for (int s = 0; s < mesh.shooterCount(); ++s) {
    const auto c = mesh.shooterCorners(s);
    const Eigen::Vector3d cross = (c[1] - c[0]).cross(c[2] - c[0]);
    shooterArea_.push_back(0.5 * cross.norm());
    shooterNormal_.push_back(cross.normalized());
  }
}

void AnalyticPatchShots::meshChanged() {
  const PatchMesh& mesh = mesh_;
  const int n = mesh.elementCount();
  partlyShadowed_.assign(n, 0);
  for (auto& row : rows_) row.reset();
  normals_.resize(n);
  centroids_.resize(n);
  receiverPoints_.resize(n);
  for (int e = 0; e < n; ++e) updateElementGeometry(e);
}

void AnalyticPatchShots::updateElementGeometry(int e) {
  const auto c = mesh_.corners(e);
  normals_[e] = mesh_.normal(e);
  centroids_[e] = (c[0] + c[1] + c[2]) / 3.0;
  receiverPoints_[e] = receiverPoints(c);  // the Gauss points (receiver_points.h)
}

void AnalyticPatchShots::meshChanged(const std::vector<int>& changed) {
  const auto start = std::chrono::steady_clock::now();
  const int n = mesh_.elementCount();
  normals_.resize(n);
  centroids_.resize(n);
  receiverPoints_.resize(n);
  partlyShadowed_.resize(n, 0);
  std::vector<char> isChanged(n, 0);
  for (int e : changed) {
    isChanged[e] = 1;
    partlyShadowed_[e] = 0;
    updateElementGeometry(e);
  }
  std::vector<size_t> freshEntry(n, SIZE_MAX);
  for (size_t k = 0; k < changed.size(); ++k) freshEntry[changed[k]] = k;
  for (int s = 0; s < shooterCount(); ++s) {
    if (!rows_[s]) continue;
    std::vector<std::array<double, 3>> fresh(changed.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, changed.size(), 16),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t k = r.begin(); k != r.end(); ++k)
                          fresh[k] = elementToShooterAtPoints(changed[k], s);
                      });
    // Unchanged receivers keep their entries as they were; changed ones get the fresh factors.
    const FormFactorRow& old = *rows_[s];
    auto row = std::make_unique<FormFactorRow>();
    std::vector<size_t> oldEntry(n, SIZE_MAX);
    for (size_t k = 0; k < old.targets.size(); ++k) oldEntry[old.targets[k]] = k;
    for (int j = 0; j < n; ++j) {
      if (isChanged[j]) {
        appendEntry(*row, s, j, fresh[freshEntry[j]]);
      } else if (oldEntry[j] != SIZE_MAX) {
        row->targets.push_back(j);
        row->values.push_back(old.values[oldEntry[j]]);
        if (!old.points.empty()) row->points.push_back(old.points[oldEntry[j]]);
      }
    }
    row->escaped = std::max(0.0, 1.0 - row->sum());
    rows_[s] = std::move(row);
  }
  seconds_ += secondsSince(start);
}

void AnalyticPatchShots::appendEntry(FormFactorRow& row, int shooter, int j,
                                     const std::array<double, 3>& f) const {
  const double mean = options_.receiverPoints == 1 ? f[0] : (f[0] + f[1] + f[2]) / 3;
  if (!(mean > 0)) return;
  // fraction_j = A_j F_js / A_s, per point and for the element (the mean).
  const double scale = mesh_.area(j) / shooterArea_[shooter];
  row.targets.push_back(j);
  row.values.push_back(mean * scale);
  if (options_.receiverPoints == 3)
    row.points.push_back({static_cast<float>(f[0] * scale), static_cast<float>(f[1] * scale),
                          static_cast<float>(f[2] * scale)});
}

double AnalyticPatchShots::elementToShooter(int receiver, int shooter) const {
  const auto f = elementToShooterAtPoints(receiver, shooter);
  return options_.receiverPoints == 1 ? f[0] : (f[0] + f[1] + f[2]) / 3;
}

std::array<double, 3> AnalyticPatchShots::elementToShooterAtPoints(int receiver,
                                                                   int shooter) const {
  const std::array<double, 3> none{0.0, 0.0, 0.0};
  if (mesh_.shooter(receiver) == shooter) return none;
  const auto source = mesh_.shooterCorners(shooter);
  const Eigen::Vector3d& n = normals_[receiver];
  const Eigen::Vector3d& ns = shooterNormal_[shooter];
  const auto receiverCorners = mesh_.corners(receiver);
  const double scale = rays_.surfaceOffset();
  // No rays for pairs that cannot exchange light.
  bool sourceAbove = false, receiverInFront = false;
  for (const auto& v : source) sourceAbove |= n.dot(v - centroids_[receiver]) > scale;
  for (const auto& v : receiverCorners) receiverInFront |= ns.dot(v - source[0]) > scale;
  if (!sourceAbove || !receiverInFront) return none;

  const std::vector<Eigen::Vector3d> polygon(source.begin(), source.end());
  const int points = options_.receiverPoints;
  const int m = options_.shadowRays;
  const int g = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(m))));
  Rng rng(
      streamKey(options_.seed, static_cast<uint64_t>(receiver), static_cast<uint64_t>(shooter)));
  std::array<double, 3> atPoint = none;
  // A shadow edge crosses the element when one receiver point sees the patch in part, or when
  // some points see it and others do not (the edge passes between them).
  bool partial = false, someSee = false, someBlocked = false;
  for (int k = 0; k < points; ++k) {
    const Eigen::Vector3d x = points == 1 ? centroids_[receiver] : receiverPoints_[receiver][k];
    const double unoccluded = pointToPolygonFormFactor(x, n, polygon);
    if (unoccluded <= 0) continue;
    const Eigen::Vector3d origin = x + scale * n;
    // Visibility over the part of the patch in front of x: points behind x's tangent plane are
    // outside the clipped polygon the form factor already integrates over.
    int visible = 0, inFront = 0;
    for (int r = 0; r < m; ++r) {
      double u = rng.uniform(), v = rng.uniform();
      if (r < g * g) {  // stratified over the shooter
        u = ((r % g) + u) / g;
        v = ((r / g) + v) / g;
      }
      const Eigen::Vector3d target = uniformPointOnTriangle(source, u, v) + scale * ns;
      if (n.dot(target - origin) <= 0) continue;
      ++inFront;
      if (!rays_.occluded(origin, target - origin, 1.0 - 1e-6)) ++visible;
    }
    raysCast_ += inFront;
    if (inFront == 0) continue;
    if (visible > 0 && visible < inFront) partial = true;
    someSee |= visible > 0;
    someBlocked |= visible < inFront;
    atPoint[k] = unoccluded * visible / inFront;
  }
  // Benign race: every writer stores 1.
  if ((partial || (someSee && someBlocked)) && (shadowCasters_.empty() || shadowCasters_[shooter]))
    partlyShadowed_[receiver] = 1;
  if (points == 1) atPoint[1] = atPoint[2] = atPoint[0];
  return atPoint;
}

double AnalyticPatchShots::elementToShooterCached(int receiver, int shooter) const {
  if (!rows_[shooter]) return elementToShooter(receiver, shooter);
  return rows_[shooter]->valueFor(receiver) * shooterArea_[shooter] / mesh_.area(receiver);
}

std::array<double, 3> AnalyticPatchShots::elementToShooterAtPointsCached(int receiver,
                                                                         int shooter) const {
  const FormFactorRow* row = rows_[shooter].get();
  if (!row) return elementToShooterAtPoints(receiver, shooter);
  const double scale = shooterArea_[shooter] / mesh_.area(receiver);
  const auto it = std::lower_bound(row->targets.begin(), row->targets.end(), receiver);
  if (it == row->targets.end() || *it != receiver) return {0.0, 0.0, 0.0};
  const size_t k = it - row->targets.begin();
  if (row->points.empty())
    return {row->values[k] * scale, row->values[k] * scale, row->values[k] * scale};
  return {row->points[k][0] * scale, row->points[k][1] * scale, row->points[k][2] * scale};
}

const FormFactorRow& AnalyticPatchShots::powerFractions(int shooter) {
  if (!rows_[shooter]) {
    const auto start = std::chrono::steady_clock::now();
    const int n = mesh_.elementCount();
    std::vector<std::array<double, 3>> factors(n);
    tbb::parallel_for(tbb::blocked_range<int>(0, n, 16), [&](const tbb::blocked_range<int>& r) {
      for (int j = r.begin(); j != r.end(); ++j) factors[j] = elementToShooterAtPoints(j, shooter);
    });
    auto row = std::make_unique<FormFactorRow>();
    for (int j = 0; j < n; ++j) appendEntry(*row, shooter, j, factors[j]);
    row->escaped = std::max(0.0, 1.0 - row->sum());
    rows_[shooter] = std::move(row);
    ++rowsComputed_;
    seconds_ += secondsSince(start);
  }
  return *rows_[shooter];
}

Eigen::SparseMatrix<double, Eigen::RowMajor> AnalyticPatchShots::gatheringMatrix(
    Progress* progress) {
  std::vector<std::vector<int>> elementsOf(shooterCount());
  for (int e = 0; e < mesh_.elementCount(); ++e) elementsOf[mesh_.shooter(e)].push_back(e);
  std::vector<Eigen::Triplet<double>> entries;
  for (int s = 0; s < shooterCount(); ++s) {
    const FormFactorRow& row = powerFractions(s);
    // fraction_j = A_j F_js / A_s, and F_je = F_js A_e / A_s, so F_je = fraction_j A_e / A_j.
    for (size_t k = 0; k < row.targets.size(); ++k) {
      const int j = row.targets[k];
      for (int e : elementsOf[s])
        entries.emplace_back(j, e, row.values[k] * mesh_.area(e) / mesh_.area(j));
    }
    if (progress) progress->advance(1);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> f(mesh_.elementCount(), mesh_.elementCount());
  f.setFromTriplets(entries.begin(), entries.end());
  return f;
}

}  // namespace rad
