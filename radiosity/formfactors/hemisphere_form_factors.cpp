#include "radiosity/formfactors/hemisphere_form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>

#include "meshing/element_stream.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/core/rng.h"
#include "radiosity/formfactors/hemisphere_sampling.h"

namespace rad {

double FormFactorRow::valueFor(int target) const {
  const auto it = std::lower_bound(targets.begin(), targets.end(), target);
  return (it != targets.end() && *it == target) ? values[it - targets.begin()] : 0.0;
}

HemisphereFormFactors::HemisphereFormFactors(const PatchMesh& mesh, const RayCaster& rays,
                                             HemisphereOptions options)
    : mesh_(mesh), rays_(rays), options_(options) {
  RAD_CHECK_GE(options_.raysPerElement, 1);
  if (!options_.rayMultiplier.empty())
    RAD_CHECK_EQ(options_.rayMultiplier.size(), mesh.elementCount());  // one per element
  normals_.resize(mesh.elementCount());
  frontNormals_.resize(3 * static_cast<size_t>(mesh.elementCount()));
  for (int e = 0; e < mesh.elementCount(); ++e) {
    normals_[e] = mesh.normal(e);
    for (int d = 0; d < 3; ++d) frontNormals_[3 * e + d] = static_cast<float>(normals_[e][d]);
  }
}

namespace {

// SplitMix64 output k of the generator keyed by `key`: counter-based, so any ray's random numbers
// come straight from (row key, ray index), on any thread, in any order.
inline uint64_t splitMix(uint64_t key, uint64_t k) {
  return mix64(key + k * 0x9e3779b97f4a7c15ull);
}
// Ray k's 23 random bits for each of its four uniforms, into slot i of a ray block.
template <class Block>
inline void drawJitter(uint64_t key, int k, Block& b, int i) {
  const uint64_t h0 = splitMix(key, 2 * static_cast<uint64_t>(k));
  const uint64_t h1 = splitMix(key, 2 * static_cast<uint64_t>(k) + 1);
  b.jitter[0][i] = static_cast<int32_t>(h0 >> 41);
  b.jitter[1][i] = static_cast<int32_t>((h0 & 0xffffffffu) >> 9);
  b.jitter[2][i] = static_cast<int32_t>(h1 >> 41);
  b.jitter[3][i] = static_cast<int32_t>((h1 & 0xffffffffu) >> 9);
}
// Uniform integer in [0, n) without a division in the common case (Lemire 2019, unbiased).
inline uint32_t below(Rng& rng, uint32_t n) {
  uint64_t m = static_cast<uint64_t>(rng.next()) * n;
  if (static_cast<uint32_t>(m) < n) {
    const uint32_t threshold = (0u - n) % n;
    while (static_cast<uint32_t>(m) < threshold) m = static_cast<uint64_t>(rng.next()) * n;
  }
  return static_cast<uint32_t>(m >> 32);
}

// Scratch space for assembling rows, one per thread, reused across rows: a hit count per element
// plus one slot for escaped rays (all zero between rows), the distinct slots hit, and a bitmap of
// them. Only used in the serial assembly, which makes no TBB call: a thread waiting in a parallel
// loop may start another row, but never inside an assembly.
struct AssemblyScratch {
  std::vector<uint32_t> count;
  std::vector<uint32_t> touched;
  std::vector<uint64_t> bits;
};
thread_local AssemblyScratch t_scratch;

// Buffers for a row's per-ray arrays, reused across rows without allocating. A thread that waits
// inside a row's parallel loop may start another row (TBB work stealing), so buffers are taken
// from and returned to the thread's stack of free ones rather than owned by the thread.
class RowBuffer {
 public:
  RowBuffer() {
    if (!free_.empty()) {
      data_ = std::move(free_.back());
      free_.pop_back();
    }
  }
  ~RowBuffer() { free_.push_back(std::move(data_)); }
  RowBuffer(const RowBuffer&) = delete;
  RowBuffer& operator=(const RowBuffer&) = delete;
  std::vector<int>& get() { return data_; }

 private:
  std::vector<int> data_;
  static thread_local std::vector<std::vector<int>> free_;
};
thread_local std::vector<std::vector<int>> RowBuffer::free_;

}  // namespace

// A block of a row's rays, structure of arrays: the uniforms, the rays as cast (floats in the
// caster's frame), the origins in double, and what each ray hit.
struct HemisphereFormFactors::RayBlock {
  static constexpr int kSize = 64;
  int count = 0;
  alignas(64) int32_t jitter[4][kSize];      // 23 random bits per uniform
  alignas(64) int32_t directionCell[kSize];  // stratum (y << 16 | x) of the direction grid
  alignas(64) float u[4][kSize];  // direction (cos² theta, azimuth turn), position on the triangle
  alignas(64) double origin[3][kSize];
  alignas(64) float castOrigin[3][kSize];
  alignas(64) float direction[3][kSize];
  alignas(64) int element[kSize];
  alignas(64) float distance[kSize];
};

HemisphereFormFactors::RowSampler::RowSampler(const HemisphereFormFactors& owner, int element,
                                              std::vector<int>& positionCell)
    : count_(owner.raysForRow(element)), positionCell_(positionCell) {
  const Frame frame(owner.normals_[element]);
  const auto corners = owner.mesh_.corners(element);
  const Eigen::Vector3d base =
      owner.rays_.liftOff(corners[0], frame.normal, frame.normal) - owner.rays_.centre();
  for (int d = 0; d < 3; ++d) {
    tangent_[d] = static_cast<float>(frame.tangent[d]);
    bitangent_[d] = static_cast<float>(frame.bitangent[d]);
    normal_[d] = static_cast<float>(frame.normal[d]);
    base_[d] = base[d];
    edge1_[d] = corners[1][d] - corners[0][d];
    edge2_[d] = corners[2][d] - corners[0][d];
  }
  // The only serial part: a shuffle pairing direction strata with position strata, from the
  // row's own stream. A g×g jittered grid stratifies the first g² rays; the rest are plain random.
  Rng rng(streamKey(owner.options_.seed, elementStream(owner.mesh_, element)));
  key_ = (static_cast<uint64_t>(rng.next()) << 32) | rng.next();
  grid_ = static_cast<int>(std::sqrt(static_cast<double>(count_)));
  if (grid_ >= 1 << 15)  // --rays at its limit, times an emitter's multiplier of up to 64
    throw InputError("a form-factor row of " + std::to_string(count_) +
                     " rays: it must have fewer than 2^30; lower --rays");
  inverseGrid_ = 1.0 / grid_;
  const int cells = grid_ * grid_;
  positionCell_.resize(cells);
  for (int y = 0, k = 0; y < grid_; ++y)
    for (int x = 0; x < grid_; ++x)
      positionCell_[k++] = y << 16 | x;  // strata packed as fill() reads them
  for (int k = cells - 1; k > 0; --k) std::swap(positionCell_[k], positionCell_[below(rng, k + 1)]);
}

void HemisphereFormFactors::RowSampler::fill(int begin, RayBlock& b) const {
  const int n = b.count;
  // The uniforms: four per ray from two counter-based draws (23 bits each), jittered inside the
  // ray's direction stratum and its shuffled position stratum; rays past the g×g grid are plain.
  const int stratified = std::min(n, std::max(0, grid_ * grid_ - begin));
  int x = 0, y = 0;
  if (stratified > 0) {
    y = begin / grid_;
    x = begin - y * grid_;
  }
  for (int i = 0; i < n; ++i) {
    drawJitter(key_, begin + i, b, i);
    b.directionCell[i] = y << 16 | x;
    if (++x == grid_) {
      x = 0;
      ++y;
    }
  }
  placeRays(b, stratified, positionCell_.data() + begin);
}

void HemisphereFormFactors::RowSampler::fillRays(const int* rays, RayBlock& b) const {
  const int n = b.count;
  const int cells = grid_ * grid_;
  int stratified = 0;  // the rays of the grid come first: `rays` increases
  alignas(64) int32_t positionCell[RayBlock::kSize];
  for (int i = 0; i < n; ++i) {
    const int k = rays[i];
    drawJitter(key_, k, b, i);
    if (k < cells) {
      const int y = k / grid_;
      b.directionCell[i] = y << 16 | (k - y * grid_);
      positionCell[i] = positionCell_[k];
      stratified = i + 1;
    }
  }
  placeRays(b, stratified, positionCell);
}

void HemisphereFormFactors::RowSampler::placeRays(RayBlock& b, int stratified,
                                                  const int* positionCell) const {
  const int n = b.count;
  // (2j + 1) / 2^24: exact in float, strictly inside (0, 1).
  constexpr float kUnit = 1.0f / 16777216.0f;
  const float inverseGrid = static_cast<float>(inverseGrid_);
  for (int i = 0; i < stratified; ++i) {
    const int32_t d = b.directionCell[i], p = positionCell[i];
    b.u[0][i] =
        (static_cast<float>(d & 0xffff) + static_cast<float>(2 * b.jitter[0][i] + 1) * kUnit) *
        inverseGrid;
    b.u[1][i] = (static_cast<float>(d >> 16) + static_cast<float>(2 * b.jitter[1][i] + 1) * kUnit) *
                inverseGrid;
    b.u[2][i] =
        (static_cast<float>(p & 0xffff) + static_cast<float>(2 * b.jitter[2][i] + 1) * kUnit) *
        inverseGrid;
    b.u[3][i] = (static_cast<float>(p >> 16) + static_cast<float>(2 * b.jitter[3][i] + 1) * kUnit) *
                inverseGrid;
  }
  for (int c = 0; c < 4; ++c)
    for (int i = stratified; i < n; ++i)
      b.u[c][i] = static_cast<float>(2 * b.jitter[c][i] + 1) * kUnit;
  // Cosine-weighted directions (cosineWeightedDirection, in float: Embree takes floats), mapped
  // by the element's frame.
  const float t0 = tangent_[0], t1 = tangent_[1], t2 = tangent_[2];
  const float b0 = bitangent_[0], b1 = bitangent_[1], b2 = bitangent_[2];
  const float n0 = normal_[0], n1 = normal_[1], n2 = normal_[2];
  for (int i = 0; i < n; ++i) {
    const float u0 = b.u[0][i];
    const float cosTheta = std::sqrt(u0), sinTheta = std::sqrt(1.0f - u0);
    float c, s;
    turnCosSin(b.u[1][i], c, s);
    const float x = sinTheta * c, y = sinTheta * s;
    b.direction[0][i] = x * t0 + y * b0 + cosTheta * n0;
    b.direction[1][i] = x * t1 + y * b1 + cosTheta * n1;
    b.direction[2][i] = x * t2 + y * b2 + cosTheta * n2;
  }
  // Uniform origins on the triangle (uniformPointOnTriangle), lifted off it.
  const std::array<double, 3> base = base_, e1 = edge1_, e2 = edge2_;  // locals: no aliasing
  for (int i = 0; i < n; ++i) {
    const double u2 = b.u[2][i], u3 = b.u[3][i];
    const double su = std::sqrt(u2);
    const double w1 = su * (1.0 - u3), w2 = su * u3;
    for (int d = 0; d < 3; ++d) {
      b.origin[d][i] = base[d] + w1 * e1[d] + w2 * e2[d];
      b.castOrigin[d][i] = static_cast<float>(b.origin[d][i]);
    }
  }
}

void HemisphereFormFactors::frontHits(int element, const RayBlock& b, int* target) const {
  // Only the front of a surface receives: a back-face hit is absorbed and counts as escaped.
  const bool partlyBuried =
      options_.exposure != nullptr && options_.exposure->buriedCells(element) != 0;
  for (int i = 0; i < b.count; ++i) {
    if (partlyBuried && options_.exposure->buried(element, b.u[2][i], b.u[3][i])) {
      target[i] = kBuriedOrigin;
      continue;
    }
    const int t = b.element[i];
    int front = -1;
    if (t >= 0 && t != element) {
      const float* n = &frontNormals_[3 * static_cast<size_t>(t)];
      if (n[0] * b.direction[0][i] + n[1] * b.direction[1][i] + n[2] * b.direction[2][i] < 0)
        front = t;
    }
    if (front >= 0 && options_.exposure != nullptr && options_.exposure->buriedCells(front) != 0) {
      const float origin[3] = {b.castOrigin[0][i], b.castOrigin[1][i], b.castOrigin[2][i]};
      const float direction[3] = {b.direction[0][i], b.direction[1][i], b.direction[2][i]};
      if (landsBuried(options_.exposure, front, origin, direction, b.distance[i])) front = -1;
    }
    target[i] = front;
  }
}

bool HemisphereFormFactors::landsBuried(const ElementExposure* exposure, int target,
                                        const float origin[3], const float direction[3],
                                        float distance) const {
  if (exposure == nullptr || exposure->buriedCells(target) == 0) return false;
  Eigen::Vector3d hit = rays_.centre();
  for (int d = 0; d < 3; ++d)
    hit[d] += static_cast<double>(origin[d]) +
              static_cast<double>(distance) * static_cast<double>(direction[d]);
  return exposure->buriedAtPoint(mesh_, target, hit);
}

namespace {
// Runs body(begin, block) over a row's rays in blocks, in parallel (each block on one thread).
template <class Body>
void forEachBlock(int count, Body&& body) {
  constexpr int kSize = 64;
  tbb::parallel_for(tbb::blocked_range<int>(0, count, kSize),
                    [&](const tbb::blocked_range<int>& range) {
                      for (int begin = range.begin(); begin < range.end(); begin += kSize)
                        body(begin, std::min(kSize, range.end() - begin));
                    });
}
}  // namespace

std::vector<RowRay> HemisphereFormFactors::traceRow(int element) const {
  std::vector<int> cells;
  const RowSampler sampler(*this, element, cells);
  std::vector<RowRay> rays(sampler.count());
  const Eigen::Vector3d& centre = rays_.centre();
  forEachBlock(sampler.count(), [&](int begin, int count) {
    RayBlock b;
    b.count = count;
    sampler.fill(begin, b);
    const float* origin[3] = {b.castOrigin[0], b.castOrigin[1], b.castOrigin[2]};
    const float* direction[3] = {b.direction[0], b.direction[1], b.direction[2]};
    rays_.closestHits(count, origin, direction, b.element, b.distance);
    int target[RayBlock::kSize];
    frontHits(element, b, target);
    for (int i = 0; i < count; ++i) {
      RowRay& ray = rays[begin + i];
      ray.origin = centre + Eigen::Vector3d(b.origin[0][i], b.origin[1][i], b.origin[2][i]);
      const Eigen::Vector3d d(b.direction[0][i], b.direction[1][i], b.direction[2][i]);
      const double length = d.norm();  // 1 within float rounding; distances are along d
      ray.direction = d / length;
      ray.distance = b.distance[i] * length;
      ray.target = std::max(target[i], -1);
    }
  });
  return rays;
}

namespace {

// The direction strata of a g×g grid (RowSampler: x over cos²θ, y over the azimuth's turn) as
// cones in the element's frame (x tangent, y bitangent, z normal): each stratum's centre
// direction and the sine and cosine of the widest angle from it to the stratum (its corners and
// edge midpoints, where that angle is largest for strata this small), padded for the rays' float
// rounding. Stratum k = y·g + x, as ray k's.
struct StratumCone {
  double x, y, z, cosRadius, sinRadius;
};
const std::vector<StratumCone>& strataCones(int g) {
  thread_local std::unordered_map<int, std::vector<StratumCone>> byGrid;  // a few sizes a scene
  std::vector<StratumCone>& cones = byGrid[g];
  if (!cones.empty()) return cones;
  auto direction = [](double u0, double u1) {
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - u0));
    return Eigen::Vector3d(sinTheta * std::cos(2 * M_PI * u1), sinTheta * std::sin(2 * M_PI * u1),
                           std::sqrt(u0));
  };
  cones.resize(static_cast<size_t>(g) * g);
  for (int y = 0; y < g; ++y)
    for (int x = 0; x < g; ++x) {
      const Eigen::Vector3d c = direction((x + 0.5) / g, (y + 0.5) / g);
      double radius = 0;
      for (int i = 0; i <= 2; ++i)
        for (int j = 0; j <= 2; ++j)
          radius = std::max(
              radius, std::acos(std::clamp(c.dot(direction((x + 0.5 * i) / g, (y + 0.5 * j) / g)),
                                           -1.0, 1.0)));
      radius = 1.02 * radius + 2e-3;
      cones[static_cast<size_t>(y) * g + x] = {c.x(), c.y(), c.z(), std::cos(radius),
                                               std::sin(radius)};
    }
  return cones;
}

}  // namespace

bool HemisphereFormFactors::raysAimedAt(int element, const RowSampler& sampler,
                                        const TriangleSetCaster& region,
                                        std::vector<int>& rays) const {
  const int g = sampler.grid();
  if (g <= 0 || sampler.count() != g * g) return false;  // rays past the grid: no strata
  // Every ray leaves from the element's bounding sphere (lifted off it by far less than the
  // margin); one that meets the region's bounding sphere points within α of the line between
  // the centres, sin α = (r_element + r_region) / distance, when the spheres are at least twice
  // that sum apart (nearer, rays leaving away from the region could still graze it).
  const auto corners = mesh_.corners(element);
  const Eigen::Vector3d centre = (corners[0] + corners[1] + corners[2]) / 3;
  double radius = 0;
  for (const auto& c : corners) radius = std::max(radius, (c - centre).norm());
  const Eigen::Vector3d regionCentre = 0.5 * (region.boundsMin() + region.boundsMax());
  radius += 0.5 * (region.boundsMax() - region.boundsMin()).norm() + 1e-4 * mesh_.boundsDiagonal();
  const Eigen::Vector3d toRegion = regionCentre - centre;
  const double distance = toRegion.norm();
  if (!(distance >= 2 * radius)) return false;
  const double sinAlpha = radius / distance, cosAlpha = std::sqrt(1 - sinAlpha * sinAlpha);
  const Frame frame(normals_[element]);
  const Eigen::Vector3d axis = toRegion / distance;
  const double ax = axis.dot(frame.tangent), ay = axis.dot(frame.bitangent),
               az = axis.dot(frame.normal);
  const std::vector<StratumCone>& cones = strataCones(g);
  rays.clear();
  for (int k = 0; k < g * g; ++k) {
    const StratumCone& s = cones[static_cast<size_t>(k)];
    // Within α + ρ of the axis: cos(angle) >= cos(α + ρ) (α + ρ < π: α ≤ 30°, ρ small).
    if (s.x * ax + s.y * ay + s.z * az >= cosAlpha * s.cosRadius - sinAlpha * s.sinRadius)
      rays.push_back(k);
  }
  return true;
}

bool HemisphereFormFactors::updateRow(int element, const std::function<double(int)>& keptFactor,
                                      double keptEscaped, RowChanges& changes, const Edit& edit,
                                      int& changedRays, int& testedRays) const {
  RAD_CHECK_MSG(options_.specular.empty(), "rows through mirrors and glass are not updated");
  changedRays = 0;
  testedRays = 0;
  changes = RowChanges();
  if (edit.region.empty()) return true;
  // Rays leave into the element's front half-space only: a region wholly behind its plane (every
  // corner of its bounds) is never met.
  {
    const Eigen::Vector3d& n = normals_[element];
    const Eigen::Vector3d p = mesh_.corners(element)[0];
    const Eigen::Vector3d& lo = edit.region.boundsMin();
    const Eigen::Vector3d& hi = edit.region.boundsMax();
    bool inFront = false;
    for (int c = 0; c < 8 && !inFront; ++c) {
      const Eigen::Vector3d corner(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(),
                                   c & 4 ? hi.z() : lo.z());
      inFront = (corner - p).dot(n) > 0;
    }
    if (!inFront) return true;
  }
  // Reused buffers (most rows of a large scene pass through here: no allocation per row).
  RowBuffer cells, aimedRays;
  const RowSampler sampler(*this, element, cells.get());
  const bool partlyBuried =
      options_.exposure != nullptr && options_.exposure->buriedCells(element) != 0;
  // The rays that meet the region no farther than their first hit, and what they hit.
  struct Changed {
    int oldTarget, newTarget;  // -1: escaped or a back face; kRemoved: the old place
  };
  constexpr int kRemoved = -3;
  std::vector<Changed> changed;
  int counted = 0;  // rays from exposed cells: the row's denominator
  RayBlock b;
  float regionDistance[RayBlock::kSize], oldDistance[RayBlock::kSize];
  int oldTriangle[RayBlock::kSize];
  float o[3][RayBlock::kSize], d[3][RayBlock::kSize];
  float meetDistance[RayBlock::kSize], hitDistance[RayBlock::kSize];
  int hit[RayBlock::kSize];
  // The rays of a filled block that meet the region no farther than their first hit: their old
  // and new targets into `changed`; `countRays`: the block's exposed rays add to `counted`.
  auto examine = [&](bool countRays) {
    const float* origin[3] = {b.castOrigin[0], b.castOrigin[1], b.castOrigin[2]};
    const float* direction[3] = {b.direction[0], b.direction[1], b.direction[2]};
    edit.region.distances(b.count, origin, direction, regionDistance);
    int m = 0;
    for (int i = 0; i < b.count; ++i) {
      if (countRays) {
        if (partlyBuried && options_.exposure->buried(element, b.u[2][i], b.u[3][i])) continue;
        ++counted;
      }
      if (!std::isfinite(regionDistance[i])) continue;
      for (int k = 0; k < 3; ++k) {
        o[k][m] = b.castOrigin[k][i];
        d[k][m] = b.direction[k][i];
      }
      meetDistance[m++] = regionDistance[i];
    }
    if (m == 0) return;
    const float* mo[3] = {o[0], o[1], o[2]};
    const float* md[3] = {d[0], d[1], d[2]};
    rays_.closestHits(m, mo, md, hit, hitDistance);
    edit.oldPlace.distances(m, mo, md, oldDistance, oldTriangle);
    // frontHits' rule: only a front face receives, and only outside its buried cells (as they
    // are now for the new hit, as the kept row was cast with for the old one).
    auto front = [&](int t, int i, float distance, const ElementExposure* exposure) {
      if (t < 0 || t == element) return -1;
      const float* n = &frontNormals_[3 * static_cast<size_t>(t)];
      if (!(n[0] * d[0][i] + n[1] * d[1][i] + n[2] * d[2][i] < 0)) return -1;
      const float origin[3] = {o[0][i], o[1][i], o[2][i]};
      const float direction[3] = {d[0][i], d[1][i], d[2][i]};
      return landsBuried(exposure, t, origin, direction, distance) ? -1 : t;
    };
    for (int i = 0; i < m; ++i) {
      // "No farther", with a margin for the rounding of the two traversals: the region's new
      // triangles are the scene's own, hit at the same distance.
      if (!(meetDistance[i] <= hitDistance[i] * (1 + 1e-5f))) continue;
      const int newTarget = front(hit[i], i, hitDistance[i], options_.exposure);
      // The first hit on what did not move: the same ray in the scene without the moved elements
      // (not continued past them, which would skip a face where a moved one lies on it, the floor
      // under a crate).
      int fixedHit = hit[i];
      float fixedDistance = hitDistance[i];
      if (fixedHit >= 0 && edit.moved[static_cast<size_t>(fixedHit)]) {
        const float* one[3] = {&o[0][i], &o[1][i], &o[2][i]};
        const float* oneD[3] = {&d[0][i], &d[1][i], &d[2][i]};
        edit.withoutMoved.closestHits(1, one, oneD, &fixedHit, &fixedDistance);
      }
      // Its old hit: on the old place, an entry left out of the kept row, or escaped (-1) when
      // it met a back face there; else what it hits past the moved elements.
      int oldTarget = front(fixedHit, i, fixedDistance,
                            edit.cellsBefore ? edit.cellsBefore : options_.exposure);
      if (oldDistance[i] < fixedDistance) {
        const float direction[3] = {d[0][i], d[1][i], d[2][i]};
        oldTarget = edit.oldPlace.meetsFront(oldTriangle[i], direction) ? kRemoved : -1;
      }
      if (oldTarget != newTarget) changed.push_back({oldTarget, newTarget});
    }
  };
  std::vector<int>& aimed = aimedRays.get();
  if (partlyBuried || !raysAimedAt(element, sampler, edit.region, aimed)) {
    // Every ray may meet the region: all of them, counting the exposed ones.
    for (int begin = 0; begin < sampler.count(); begin += RayBlock::kSize) {
      b.count = std::min(RayBlock::kSize, sampler.count() - begin);
      sampler.fill(begin, b);
      testedRays += b.count;
      examine(true);
    }
  } else {
    // Only the rays whose direction stratum points at the region; the element has no buried
    // part, so every ray counts.
    counted = sampler.count();
    for (size_t begin = 0; begin < aimed.size(); begin += RayBlock::kSize) {
      b.count = static_cast<int>(std::min<size_t>(RayBlock::kSize, aimed.size() - begin));
      sampler.fillRays(aimed.data() + begin, b);
      testedRays += b.count;
      examine(false);
    }
  }
  changedRays = static_cast<int>(changed.size());
  changes.counted = counted;
  if (changed.empty()) return true;
  // Counts from the kept row's fractions (exact: count / counted is what assemble stored); the
  // changes, a few per row, sorted by target (-1: escaped, first), summed per target.
  std::vector<std::pair<int, int>> delta;  // target, change in its count
  delta.reserve(2 * changed.size());       // each change: -1 and +1
  for (const Changed& c : changed) {
    if (c.oldTarget != kRemoved) delta.emplace_back(c.oldTarget, -1);
    delta.emplace_back(c.newTarget, 1);
  }
  std::sort(delta.begin(), delta.end());
  size_t j = 0;
  for (; j < delta.size() && delta[j].first < 0; ++j) changes.escaped += delta[j].second;
  if (std::llround(keptEscaped * counted) + changes.escaped < 0) return false;
  while (j < delta.size()) {
    const int target = delta[j].first;
    int sum = 0;
    for (; j < delta.size() && delta[j].first == target; ++j) sum += delta[j].second;
    if (sum == 0) continue;
    if (std::llround(keptFactor(target) * counted) + sum < 0) return false;
    changes.counts.emplace_back(target, sum);
  }
  return true;
}

FormFactorRow HemisphereFormFactors::computeRow(int element) const {
  RowBuffer cells, hits;
  const RowSampler sampler(*this, element, cells.get());
  const int n = sampler.count();
  std::vector<int>& firstHit = hits.get();
  firstHit.resize(n);  // each ray writes only its own entry
  const bool extended = !options_.specular.empty();
  std::vector<Rgb> weight(extended ? n : 0);
  const uint64_t stream = extended ? elementStream(mesh_, element) : 0;
  forEachBlock(n, [&](int begin, int count) {
    RayBlock b;
    b.count = count;
    sampler.fill(begin, b);
    if (!extended) {
      const float* origin[3] = {b.castOrigin[0], b.castOrigin[1], b.castOrigin[2]};
      const float* direction[3] = {b.direction[0], b.direction[1], b.direction[2]};
      rays_.closestHits(count, origin, direction, b.element, b.distance);
      frontHits(element, b, &firstHit[begin]);
      return;
    }
    const Eigen::Vector3d& centre = rays_.centre();
    for (int i = 0; i < count; ++i) {
      const int k = begin + i;
      const Eigen::Vector3d origin =
          centre + Eigen::Vector3d(b.origin[0][i], b.origin[1][i], b.origin[2][i]);
      const Eigen::Vector3d direction =
          Eigen::Vector3d(b.direction[0][i], b.direction[1][i], b.direction[2][i]).normalized();
      // Fresnel choices draw from the ray's own stream: reproducible on any thread count.
      Rng pathRng(streamKey(options_.seed, stream, static_cast<uint64_t>(k) + 1));
      int rays = 0;
      const SpecularPathEnd end = traceThroughSpecular(rays_, normals_, options_.specular, origin,
                                                       direction, element, pathRng, &rays);
      firstHit[k] = -1;
      if (options_.exposure != nullptr &&
          options_.exposure->buried(element, b.u[2][i], b.u[3][i])) {
        firstHit[k] = kBuriedOrigin;
      } else if (end.element >= 0 && end.element != element &&
                 !(options_.exposure != nullptr &&
                   options_.exposure->buriedAtPoint(mesh_, end.element, end.point))) {
        firstHit[k] = end.element;
        weight[k] = end.weight;
      }
      extraRays_ += rays - 1;
    }
  });
  return extended ? assembleTinted(firstHit, weight) : assemble(firstHit);
}

FormFactorRow HemisphereFormFactors::assemble(const std::vector<int>& firstHit) const {
  // Hit counts per element in a dense array, then the touched elements in order: sorted when
  // they are few next to the elements, else read off a bitmap of them (one bit per element, so a
  // pass over it costs elements / 64 words). The counting and marking loops have no branches
  // that depend on the hits, which are random.
  AssemblyScratch& scratch = t_scratch;
  const int n = static_cast<int>(firstHit.size());
  const uint32_t escapedSlot = static_cast<uint32_t>(mesh_.elementCount());
  scratch.count.resize(escapedSlot + 1, 0);
  scratch.touched.resize(n + 1);
  uint32_t* count = scratch.count.data();
  uint32_t* touched = scratch.touched.data();
  size_t m = 0;
  int dropped = 0;  // rays from buried cells
  for (int t : firstHit) {
    if (t == kBuriedOrigin) {
      ++dropped;
      continue;
    }
    const uint32_t slot = t < 0 ? escapedSlot : static_cast<uint32_t>(t);
    touched[m] = slot;
    m += count[slot]++ == 0;
  }
  FormFactorRow row;
  const double perRay = dropped < n ? 1.0 / (n - dropped) : 0.0;
  row.escaped = dropped < n ? count[escapedSlot] * perRay : 1.0;  // all buried: none shot
  const bool anyEscaped = count[escapedSlot] > 0;
  if (anyEscaped) --m;  // the escaped slot is no target
  count[escapedSlot] = 0;
  row.targets.resize(m);
  row.values.resize(m);
  size_t j = 0;
  auto emit = [&](uint32_t t) {
    row.targets[j] = static_cast<int>(t);
    row.values[j++] = count[t] * perRay;
    count[t] = 0;
  };
  if (m * 512 < escapedSlot) {
    std::sort(touched, touched + m + anyEscaped);
    for (size_t k = 0; k < m; ++k) emit(touched[k]);  // the escaped slot, if any, sorts last
  } else {
    scratch.bits.assign(escapedSlot / 64 + 1, 0);
    uint64_t* bits = scratch.bits.data();
    for (size_t k = 0; k < m + anyEscaped; ++k)
      bits[touched[k] >> 6] |= uint64_t(1) << (touched[k] & 63);
    for (size_t w = 0; j < m; ++w)
      for (uint64_t word = bits[w]; word != 0 && j < m; word &= word - 1)
        emit(static_cast<uint32_t>(64 * w + __builtin_ctzll(word)));
  }
  return row;
}

FormFactorRow HemisphereFormFactors::assembleTinted(const std::vector<int>& firstHit,
                                                    const std::vector<Rgb>& weight) const {
  // Group rays by target (sorting a permutation keeps each ray's weight with it).
  const int n = static_cast<int>(firstHit.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return firstHit[a] < firstHit[b]; });
  FormFactorRow row;
  const int dropped = static_cast<int>(std::count(firstHit.begin(), firstHit.end(), kBuriedOrigin));
  const double perRay = dropped < n ? 1.0 / (n - dropped) : 0.0;
  size_t k = 0;
  while (k < order.size() && firstHit[order[k]] < 0) ++k;
  row.escaped = dropped < n ? (k - dropped) * perRay : 1.0;
  bool anyTint = false;
  while (k < order.size()) {
    const int target = firstHit[order[k]];
    size_t end = k;
    Rgb tint;
    while (end < order.size() && firstHit[order[end]] == target) {
      tint += weight[order[end]] * perRay;
      ++end;
    }
    row.targets.push_back(target);
    row.values.push_back((end - k) * perRay);
    anyTint |= !(tint.r == tint.g && tint.g == tint.b && tint.r == row.values.back());
    row.tinted.push_back(tint);
    k = end;
  }
  if (!anyTint) row.tinted.clear();  // every path was untinted: a plain row
  return row;
}

}  // namespace rad
