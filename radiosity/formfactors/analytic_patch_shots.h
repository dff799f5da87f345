#pragma once

#include <Eigen/SparseCore>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiosity/formfactors/shot_rows.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {

class Progress;

struct AnalyticOptions {
  int receiverPoints = 3;  // 1: the centroid; 3: the degree-2 Gauss points of the triangle
  int shadowRays = 16;     // per receiver point and shooter, stratified over the shooter
  uint64_t seed = 1;
};

// Element-to-patch form factors in the manner of Wallace, Elmquist and Haines (1989): at sample
// points x of the receiving element, the exact point-to-polygon form factor to the shooting
// patch (Lambert/Nusselt), times the fraction of shadow rays from x to stratified points of the
// patch that arrive unblocked. Patches shoot, elements receive (substructuring, Cohen et al.
// 1986): the shooters are PatchMesh's shooting patches, coarser than the elements.
//
// Pairs that cannot exchange light get no rays: a patch entirely behind the receiver's plane,
// a receiver entirely behind the patch's plane (emitters and receivers are one-sided), coplanar
// pairs. Shadow-ray points come from a stream keyed by (seed, receiver, shooter), so results do
// not depend on thread count or on the order rows are computed.
class AnalyticPatchShots : public ShotRows {
 public:
  AnalyticPatchShots(const PatchMesh& mesh, const RayCaster& rays, AnalyticOptions options);

  // After the mesh's elements were refined (shooters unchanged): refreshes the per-element data
  // and forgets the cached rows, whose element indices are stale. The BVH need not change:
  // bisection keeps the surfaces exactly where they were, and visibility needs no element ids.
  void meshChanged();
  // The same after a refinement that changed only the `changed` elements (new ones, or ones whose
  // corners moved): the rows already computed keep every other entry, which split_copy's stable
  // element indices and the (seed, receiver, shooter) streams leave exactly as a fresh computation
  // would give them, and recompute only the changed receivers. A pass then costs what it changed.
  void meshChanged(const std::vector<int>& changed);

  // F from element `receiver` to shooting patch `shooter`, visibility included.
  double elementToShooter(int receiver, int shooter) const;
  // The same, read from the shooter's row when it is already computed (no rays).
  double elementToShooterCached(int receiver, int shooter) const;
  // The point factors whose mean is elementToShooter(): at each of the element's receiver points
  // (the Gauss points, near corners 0, 1, 2 in PatchMesh::corners order; all three the centroid's
  // value with one receiver point). Read from the shooter's row when it is already computed.
  std::array<double, 3> elementToShooterAtPointsCached(int receiver, int shooter) const;

  int shooterCount() const override { return mesh_.shooterCount(); }
  int shooterOf(int element) const override { return mesh_.shooter(element); }
  double shooterArea(int shooter) const override { return shooterArea_[shooter]; }
  // Fractions A_j F_js / A_s of the power of shooter s that land on each element j (reciprocity),
  // computed on the first request in parallel over the receivers, then kept.
  const FormFactorRow& powerFractions(int shooter) override;
  std::string description() const override { return "patches to elements (analytic, shadow rays)"; }

  // Element-to-element gathering matrix for Jacobi / Gauss–Seidel: F_ie = F_i,s(e) · A_e / A_s(e),
  // i.e. element i gathers the area-weighted radiosity of each patch. Computes every row.
  Eigen::SparseMatrix<double, Eigen::RowMajor> gatheringMatrix(Progress* progress = nullptr);

  uint64_t raysCast() const { return raysCast_.load(); }
  int rowsComputed() const { return rowsComputed_; }
  double seconds() const { return seconds_; }
  // Shooters whose shadows count for partlyShadowed() (typically those holding emitters);
  // empty: every shooter.
  void setShadowCasters(std::vector<char> shooters) { shadowCasters_ = std::move(shooters); }
  // Elements that saw a shadow-casting shooter only partly (a shadow boundary crosses them).
  const std::vector<char>& partlyShadowed() const { return partlyShadowed_; }

 private:
  void updateElementGeometry(int element);
  std::array<double, 3> elementToShooterAtPoints(int receiver, int shooter) const;
  // Adds receiver j's entry to a row of `shooter` from its point factors (none when zero).
  void appendEntry(FormFactorRow& row, int shooter, int j,
                   const std::array<double, 3>& pointFactors) const;

  const PatchMesh& mesh_;
  const RayCaster& rays_;
  AnalyticOptions options_;
  std::vector<Eigen::Vector3d> normals_, centroids_;
  std::vector<std::array<Eigen::Vector3d, 3>> receiverPoints_;
  std::vector<double> shooterArea_;
  std::vector<Eigen::Vector3d> shooterNormal_;
  std::vector<std::unique_ptr<FormFactorRow>> rows_;
  mutable std::atomic<uint64_t> raysCast_{0};
  mutable std::vector<char> partlyShadowed_;
  std::vector<char> shadowCasters_;
  int rowsComputed_ = 0;
  double seconds_ = 0;
};

}  // namespace rad
