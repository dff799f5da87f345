#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "meshing/patch_mesh.h"
#include "radiosity/formfactors/form_factor_row.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/formfactors/specular_paths.h"
#include "radiosity/visibility/element_exposure.h"
#include "radiosity/visibility/ray_caster.h"
#include "radiosity/visibility/triangle_set_caster.h"

namespace rad {

// One ray of a row as cast: for drawing a row in the viewer and for checking it.
struct RowRay {
  Eigen::Vector3d origin, direction;  // direction is unit length
  double distance = 0;                // to the first hit; infinite when the ray left the scene
  int target = -1;                    // element whose front it hit; -1: escaped or a back face
};

struct HemisphereOptions {
  int raysPerElement = 1024;
  uint64_t seed = 1;
  // Optional per-element multiplier of raysPerElement (empty: 1 everywhere). Used to give the
  // rows of emitters, which carry all the direct light, as many rays as they need.
  std::vector<int> rayMultiplier = {};
  // Per-element specular behaviour; empty when the scene has no mirror or glass, and then no
  // ray ever continues past its first hit.
  std::vector<SpecularSurface> specular = {};
  // Optional: the buried parts of elements (element_exposure.h). Rays whose origin lies in a
  // buried cell are dropped and the row is the fraction of the others, so an element shoots from
  // its exposed part only. Must outlive the form factors.
  const ElementExposure* exposure = nullptr;
};

// Form factors by cosine-weighted hemisphere ray casting (Monte Carlo "gathering" estimate):
// rays leave uniformly distributed points on element i with cosine-weighted directions, and
// F_ij = (rays whose first hit is the front of j) / (rays cast from i's exposed part). Origins and
// directions are stratified (a jittered grid over directions, paired with a shuffled jittered grid
// over the element) to lower the variance without bias. Rows are assembled from hit counts in a
// dense per-thread array (no sort of the rays, no allocation per ray): the work on top of the ray
// casts stays small next to them (bench/throughput).
//
// Extended form factors: a ray whose first hit is a mirror or glass continues (see
// traceThroughSpecular) to the diffuse element it finally reaches, carrying the specular
// reflectance or transmittance, so light through mirrors and glass lands inside the
// view-independent solution. Mirror and glass elements never receive.
//
// Each row draws from its own random stream keyed by (seed, element), so a row is the same
// whether it is computed alone (lazily, for shooting) or with all others, on any thread count.
class HemisphereFormFactors {
 public:
  HemisphereFormFactors(const PatchMesh& mesh, const RayCaster& rays, HemisphereOptions options);

  FormFactorRow computeRow(int element) const;  // uses TBB across the row's rays
  // The first segments of the rays computeRow(element) casts, with what each one hit first.
  std::vector<RowRay> traceRow(int element) const;
  // An edit of the geometry (`update`): its region, the triangles of what changed where they were
  // and where they are now (the scene holding the latter), the old place alone, and which of the
  // scene's elements are moved or new.
  struct Edit {
    const TriangleSetCaster& region;
    const TriangleSetCaster& oldPlace;
    const std::vector<char>& moved;
    const RayCaster& withoutMoved;  // the scene without the moved elements, in the same frame
    // The buried cells the kept rows were cast with, per element now (a ray landing in one was
    // lost), or nullptr where they are the exposure's now. The region must hold every element
    // whose cells changed, so that the rays reaching it are examined.
    const ElementExposure* cellsBefore = nullptr;
  };
  // Brings element's row from before the edit up to date ray by ray, casting only the rays that
  // meet the edit's region no farther than their first hit in the scene: `changes` says how its
  // counts change (the row itself is not made: the caller merges them into the kept row).
  // `keptFactor(t)`: the kept row's factor to target t of the scene's elements (0 for none, and
  // for elements no longer there); `keptEscaped` its escaped fraction. The rays are the
  // very rays computeRow(element) casts (the same random streams). A ray whose first hit comes
  // before the region hits the same element before and after the edit; one that meets it first
  // has its new hit added and its old one taken away: the first of its hit on the old place (an
  // entry already left out, or escaped where it met a back face there) and its first hit on what
  // did not move (the same ray cast at `withoutMoved`). So the row becomes, count for count, the
  // row computeRow would give, when the element itself did not move and its exposed cells are the
  // same (but for a ray meeting two triangles at one distance, a tie two BVHs may break either
  // way). `changedRays` counts the rays whose hit changed. Returns false when a count would fall
  // below zero (such a tie): cast the row again. Scenes with mirrors or glass: rays continue
  // past their first hit, so not answered (RAD_CHECK). Only the rays whose direction stratum can
  // point at the region from the element are made at all: `testedRays` counts them.
  bool updateRow(int element, const std::function<double(int)>& keptFactor, double keptEscaped,
                 RowChanges& changes, const Edit& edit, int& changedRays, int& testedRays) const;
  int raysForRow(int element) const {
    return options_.rayMultiplier.empty()
               ? options_.raysPerElement
               : options_.raysPerElement * options_.rayMultiplier[element];
  }
  const PatchMesh& mesh() const { return mesh_; }
  // The area element i shoots from: all of it, or its exposed part (as makeProblem's area).
  double shootingArea(int element) const {
    return mesh_.area(element) *
           (options_.exposure ? options_.exposure->exposedFraction(element) : 1.0);
  }
  // Rays cast beyond the first one of each sample: the continuations through mirrors and glass.
  uint64_t specularRays() const { return extraRays_.load(); }

 private:
  struct RayBlock;
  // The rays of one row. Their random numbers come from a counter-based generator keyed by the
  // row's own stream, so ray k is the same on any thread; only the shuffle that pairs direction
  // strata with position strata is drawn serially, once per row. Rays are made a block at a time
  // in structure-of-arrays form, so the square roots, the azimuth's sine and cosine and the
  // frame and triangle maps run as vector loops.
  class RowSampler {
   public:
    RowSampler(const HemisphereFormFactors& owner, int element, std::vector<int>& positionCell);
    int count() const { return count_; }
    // Side of the g×g jittered grid of direction strata: ray k < g² has the stratum
    // (x, y) = (k mod g, k div g), x over cos²θ and y over the azimuth's turn.
    int grid() const { return grid_; }
    // Rays begin … begin + block.count - 1, in the caster's frame (see RayCaster::centre()).
    void fill(int begin, RayBlock& block) const;
    // Rays rays[0] … rays[block.count - 1] (increasing), the same rays fill makes for them.
    void fillRays(const int* rays, RayBlock& block) const;

   private:
    // The uniforms, directions and origins of a block whose jitters and direction strata are set:
    // its first `stratified` rays in the grid, with position strata positionCell[0 …].
    void placeRays(RayBlock& block, int stratified, const int* positionCell) const;

    int count_, grid_ = 0;
    double inverseGrid_ = 0;
    std::array<float, 3> tangent_, bitangent_, normal_;  // the element's frame, as Embree's floats
    // Origins are placed in double (base: corner 0 minus the BVH centre, lifted off the surface),
    // then rounded once, as RayCaster::closestHit rounds them.
    std::array<double, 3> base_, edge1_, edge2_;
    std::vector<int>& positionCell_;  // ray k's position stratum, y << 16 | x
    uint64_t key_ = 0;
  };
  // The rays of `sampler` (element's row) whose direction stratum can point at `region` from
  // some point of the element, into `rays` (increasing); false when no ray can be ruled out so
  // (the region within twice the two bounding spheres' radii, or rays past the grid). The others
  // cannot meet it: updateRow need not make them.
  bool raysAimedAt(int element, const RowSampler& sampler, const TriangleSetCaster& region,
                   std::vector<int>& rays) const;
  // Each ray's first hit in a cast block: the element whose front it hit first, -1, or
  // kBuriedOrigin for a ray that left a buried part of the element (not counted in the row).
  static constexpr int kBuriedOrigin = -2;
  void frontHits(int element, const RayBlock& block, int* target) const;
  // Whether a ray cast from `origin` (the caster's frame, the floats as cast) along `direction`,
  // whose first hit at `distance` is the front of element `target`, lands in a buried cell of
  // it. No light reaches there (the ray slipped through the crack where a box meets the floor,
  // and the element's values are per exposed area), so such a ray is lost like one meeting a
  // back face. Only targets with buried cells cost more than a look-up.
  bool landsBuried(const ElementExposure* exposure, int target, const float origin[3],
                   const float direction[3], float distance) const;
  // Rows from each ray's first hit (-1: escaped): plain counts, or with each path's tint.
  FormFactorRow assemble(const std::vector<int>& firstHit) const;
  FormFactorRow assembleTinted(const std::vector<int>& firstHit,
                               const std::vector<Rgb>& weight) const;

  const PatchMesh& mesh_;
  const RayCaster& rays_;
  HemisphereOptions options_;
  std::vector<Eigen::Vector3d> normals_;  // per element, for specular continuation
  std::vector<float> frontNormals_;       // x, y, z per element as floats, looked up once per hit
  mutable std::atomic<uint64_t> extraRays_{0};
};

}  // namespace rad
