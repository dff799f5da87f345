#include "radiosity/formfactors/hemisphere_form_factors.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

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
  if (options_.raysPerElement < 1) throw std::invalid_argument("rays per element must be >= 1");
  if (!options_.rayMultiplier.empty() &&
      options_.rayMultiplier.size() != static_cast<size_t>(mesh.elementCount()))
    throw std::invalid_argument("one ray multiplier per element expected");
  normals_.resize(mesh.elementCount());
  for (int e = 0; e < mesh.elementCount(); ++e) normals_[e] = mesh.normal(e);
}

namespace {

// SplitMix64 output k of the generator keyed by `key`: counter-based, so any ray's random numbers
// come straight from (row key, ray index), on any thread, in any order.
inline uint64_t splitMix(uint64_t key, uint64_t k) { return mix64(key + k * 0x9e3779b97f4a7c15ull); }
// Two uniforms in (0, 1) from one 64-bit value (32 bits each: ample inside a stratum).
inline void twoUniforms(uint64_t bits, double& a, double& b) {
  constexpr double kScale = 1.0 / 4294967296.0;
  a = (static_cast<double>(bits >> 32) + 0.5) * kScale;
  b = (static_cast<double>(bits & 0xffffffffull) + 0.5) * kScale;
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

// Cosine-weighted direction about +z as cosineWeightedDirection(u1, u2), with the azimuth's
// cosine and sine from the float sincos (a third of the double's cost; the directions go to
// Embree as floats anyway), renormalised by one Newton step of 1/sqrt(c² + s²) about 1: float
// rounding leaves c² + s² within 1e-6 of 1, so the step brings the length to 1 within 1e-12.
inline Eigen::Vector3d cosineWeightedDirectionFast(double u1, double u2) {
  float sf, cf;
  ::sincosf(static_cast<float>(2.0 * M_PI * u2), &sf, &cf);
  const double c = cf, s = sf;
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - u1)) * (1.5 - 0.5 * (c * c + s * s));
  return {sinTheta * c, sinTheta * s, std::sqrt(u1)};
}

// Scratch space for assembling rows, one per thread, reused across rows: a hit count per element
// (all zero between rows) and the elements with a non-zero count. Only used in the serial
// assembly, which makes no TBB call: a thread waiting in a parallel loop may start another row,
// but never inside an assembly.
struct AssemblyScratch {
  std::vector<uint32_t> count;
  std::vector<int> touched;
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

HemisphereFormFactors::RowSampler::RowSampler(const HemisphereFormFactors& owner, int element,
                                              std::vector<int>& positionCell)
    : owner_(owner), count_(owner.raysForRow(element)), frame_(owner.normals_[element]),
      corners_(owner.mesh_.corners(element)), positionCell_(positionCell) {
  // The only serial part: a shuffle pairing direction strata with position strata, from the
  // row's own stream. A g×g jittered grid stratifies the first g² rays; the rest are plain random.
  Rng rng(streamKey(owner.options_.seed, static_cast<uint64_t>(element)));
  key_ = (static_cast<uint64_t>(rng.next()) << 32) | rng.next();
  grid_ = static_cast<int>(std::sqrt(static_cast<double>(count_)));
  inverseGrid_ = 1.0 / grid_;
  const int cells = grid_ * grid_;
  positionCell_.resize(cells);
  std::iota(positionCell_.begin(), positionCell_.end(), 0);
  for (int k = cells - 1; k > 0; --k) std::swap(positionCell_[k], positionCell_[below(rng, k + 1)]);
}

void HemisphereFormFactors::RowSampler::ray(int k, Eigen::Vector3d& origin, Eigen::Vector3d& direction) const {
  double s0, s1, s2, s3;
  twoUniforms(splitMix(key_, 2 * static_cast<uint64_t>(k)), s0, s1);
  twoUniforms(splitMix(key_, 2 * static_cast<uint64_t>(k) + 1), s2, s3);
  if (k < grid_ * grid_) {
    const int p = positionCell_[k];
    // k / grid without an integer division: (k + 0.5) / grid is never within rounding of an integer.
    const int ky = static_cast<int>((k + 0.5) * inverseGrid_), py = static_cast<int>((p + 0.5) * inverseGrid_);
    s0 = ((k - ky * grid_) + s0) * inverseGrid_;  // direction stratum k
    s1 = (ky + s1) * inverseGrid_;
    s2 = ((p - py * grid_) + s2) * inverseGrid_;  // shuffled position stratum
    s3 = (py + s3) * inverseGrid_;
  }
  direction = frame_.toWorld(cosineWeightedDirectionFast(s0, s1));
  origin = owner_.rays_.liftOff(uniformPointOnTriangle(corners_, s2, s3), frame_.normal, frame_.normal);
}

int HemisphereFormFactors::frontHit(int element, const RayHit& hit, const Eigen::Vector3d& direction) const {
  // Only the front of a surface receives: a back-face hit is absorbed and counts as escaped.
  return (hit.hit() && hit.element != element && normals_[hit.element].dot(direction) < 0) ? hit.element : -1;
}

std::vector<RowRay> HemisphereFormFactors::traceRow(int element) const {
  std::vector<int> cells;
  const RowSampler sampler(*this, element, cells);
  std::vector<RowRay> rays(sampler.count());
  tbb::parallel_for(tbb::blocked_range<int>(0, sampler.count(), 64), [&](const tbb::blocked_range<int>& range) {
    for (int k = range.begin(); k != range.end(); ++k) {
      RowRay& ray = rays[k];
      sampler.ray(k, ray.origin, ray.direction);
      const RayHit hit = rays_.closestHit(ray.origin, ray.direction);
      ray.distance = hit.distance;
      ray.target = frontHit(element, hit, ray.direction);
    }
  });
  return rays;
}

FormFactorRow HemisphereFormFactors::computeRow(int element) const {
  RowBuffer cells, hits;
  const RowSampler sampler(*this, element, cells.get());
  const int n = sampler.count();
  std::vector<int>& firstHit = hits.get();
  firstHit.assign(n, -1);  // each ray writes only its own entry
  const bool extended = !options_.specular.empty();
  std::vector<Rgb> weight(extended ? n : 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, n, 64), [&](const tbb::blocked_range<int>& range) {
    for (int k = range.begin(); k != range.end(); ++k) {
      Eigen::Vector3d origin, direction;
      sampler.ray(k, origin, direction);
      if (!extended) {
        firstHit[k] = frontHit(element, rays_.closestHit(origin, direction), direction);
        continue;
      }
      // Fresnel choices draw from the ray's own stream: reproducible on any thread count.
      Rng pathRng(streamKey(options_.seed, static_cast<uint64_t>(element), static_cast<uint64_t>(k) + 1));
      int rays = 0;
      const SpecularPathEnd end = traceThroughSpecular(rays_, normals_, options_.specular, origin, direction,
                                                       element, pathRng, options_.maxSpecularDepth, &rays);
      if (end.element >= 0 && end.element != element) {
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
  // they are few, read off the dense array when a sort would cost more than a pass over it.
  AssemblyScratch& scratch = t_scratch;
  const int n = static_cast<int>(firstHit.size());
  scratch.count.resize(mesh_.elementCount(), 0);
  scratch.touched.clear();
  int escaped = 0;
  for (int t : firstHit) {
    if (t < 0) {
      ++escaped;
    } else if (scratch.count[t]++ == 0) {
      scratch.touched.push_back(t);
    }
  }
  const size_t m = scratch.touched.size();
  FormFactorRow row;
  row.targets.reserve(m);
  row.values.reserve(m);
  const double perRay = 1.0 / n;
  row.escaped = escaped * perRay;
  auto emit = [&](int t) {
    row.targets.push_back(t);
    row.values.push_back(scratch.count[t] * perRay);
    scratch.count[t] = 0;
  };
  if (m * 16 < scratch.count.size()) {
    std::sort(scratch.touched.begin(), scratch.touched.end());
    for (int t : scratch.touched) emit(t);
  } else {
    for (int t = 0; row.targets.size() < m; ++t)
      if (scratch.count[t] > 0) emit(t);
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
  const double perRay = 1.0 / n;
  size_t k = 0;
  while (k < order.size() && firstHit[order[k]] < 0) ++k;
  row.escaped = k * perRay;
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
