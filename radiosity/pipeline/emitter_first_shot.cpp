#include "radiosity/pipeline/emitter_first_shot.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "meshing/element_stream.h"
#include "radiosity/core/check.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "radiosity/pipeline/exposed_strata.h"

namespace rad {

namespace {
constexpr int kVisibilityAttempts = 4;
// Beyond this many of an emitting element's radii, a point of it stands for it (directAt).
constexpr double kFarRadii = 4;
}  // namespace

EmitterFirstShot::EmitterFirstShot(const PatchMesh& mesh, const RayCaster& rays,
                                   const ElementExposure& exposure, uint64_t seed,
                                   int raysPerElement, double largeEmitterShare)
    : mesh_(mesh),
      rays_(rays),
      exposure_(exposure),
      seed_(seed),
      raysPerPoint_(std::max(1, raysPerElement / (kAreaStrata * kAreaStrata))),
      largeEmitterShare_(largeEmitterShare) {}

void EmitterFirstShot::apply(RadiosityProblem& problem) {
  RAD_CHECK(problem.size() == mesh_.elementCount());
  double sceneArea = 0;
  for (int e = 0; e < problem.size(); ++e) sceneArea += mesh_.area(e);
  double emittingArea = 0;
  for (int e = 0; e < problem.size(); ++e) {
    // The emitter's whole area: a buried part of an emitter still emits into its enclosure, where
    // no ray from an exposed receiver reaches it.
    const double power = emitterPower(mesh_.area(e), problem.emission[e]);
    if (power <= 0) continue;
    if (mesh_.patchArea(mesh_.patch(e)) > largeEmitterShare_ * sceneArea) continue;
    emitters_.push_back(e);
    emittingArea += mesh_.area(e);
  }
  // Many small emitters together: the links' rays find them as often as one large one.
  if (emittingArea > largeEmitterShare_ * sceneArea) emitters_.clear();
  if (emitters_.empty()) return;
  sortAlongSpace();
  std::vector<double> powers;
  for (int e : emitters_) powers.push_back(emitterPower(mesh_.area(e), problem.emission[e]));
  power_ = PowerDistribution(powers);

  emission_.assign(problem.size(), Rgb());  // E of the emitters shot here; the rest stays
  for (int e : emitters_) emission_[e] = problem.emission[e];
  irradiance_.assign(problem.size(), Rgb());
  std::atomic<uint64_t> cast{0};
  tbb::parallel_for(
      tbb::blocked_range<int>(0, problem.size(), 64), [&](const tbb::blocked_range<int>& range) {
        uint64_t local = 0;
        for (int e = range.begin(); e < range.end(); ++e) {
          if (problem.reflectance[e].maxComponent() <= 0) continue;
          const Eigen::Vector3d n = mesh_.normal(e);
          Rng rng(streamKey(seed_ ^ stream_tag::kEmitterFirstShot, elementStream(mesh_, e)));
          Rgb sum;
          const int used = forEachExposedStratum(
              mesh_, &exposure_, e, rng,
              [&](const Eigen::Vector3d& x, int) { sum += directAt(x, n, rng); });
          local += static_cast<uint64_t>(used) * raysPerPoint_;
          irradiance_[e] = used > 0 ? sum / used : Rgb();
        }
        cast += local;
      });
  raysCast_ = cast;
  for (int e = 0; e < problem.size(); ++e)
    problem.emission[e] += problem.reflectance[e] * irradiance_[e] - emission_[e];
}

// Morton order of the emitters' centroids (10 bits an axis over their bounds): neighbours in the
// order are neighbours in space, so equal steps along the cumulative power are spread over it.
void EmitterFirstShot::sortAlongSpace() {
  Eigen::Vector3d lo = mesh_.centroid(emitters_.front()), hi = lo;
  for (int e : emitters_) {
    lo = lo.cwiseMin(mesh_.centroid(e));
    hi = hi.cwiseMax(mesh_.centroid(e));
  }
  const Eigen::Vector3d extent = (hi - lo).cwiseMax(Eigen::Vector3d::Constant(1e-30));
  const auto spread = [](uint64_t v) {  // 10 bits to every third of 30
    uint64_t out = 0;
    for (int bit = 0; bit < 10; ++bit) out |= ((v >> bit) & 1) << (3 * bit);
    return out;
  };
  std::vector<std::pair<uint64_t, int>> keyed;
  keyed.reserve(emitters_.size());
  for (int e : emitters_) {
    const Eigen::Vector3d at = (mesh_.centroid(e) - lo).cwiseQuotient(extent) * 1023.0;
    uint64_t key = 0;
    for (int a = 0; a < 3; ++a)
      key |= spread(static_cast<uint64_t>(std::clamp(at[a], 0.0, 1023.0))) << a;
    keyed.emplace_back(key, e);
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t k = 0; k < keyed.size(); ++k) emitters_[k] = keyed[k].second;
}

bool EmitterFirstShot::visible(const Eigen::Vector3d& x, const Eigen::Vector3d& n,
                               const Eigen::Vector3d& y, const Eigen::Vector3d& ny) const {
  const Eigen::Vector3d w = (y - x).normalized();
  // Both ends lifted off their surfaces, towards each other: a ray from the lifted receiver point
  // along x → y alone would meet the emitter's plane before y at grazing angles.
  const Eigen::Vector3d from = rays_.liftOff(x, n, w);
  const Eigen::Vector3d to = rays_.liftOff(y, ny, -w);
  const Eigen::Vector3d along = to - from;
  const double length = along.norm();
  return !(length > 0 && rays_.occluded(from, along / length, length));
}

Rgb EmitterFirstShot::directAt(const Eigen::Vector3d& x, const Eigen::Vector3d& n, Rng& rng) const {
  Rgb sum;
  std::vector<Eigen::Vector3d> triangle(3);
  for (int k = 0; k < raysPerPoint_; ++k) {
    // Stratified along the emitters' power in space order (sortAlongSpace): the samples of one
    // point spread over the emitter as a jittered grid would, so a penumbra's visibility is
    // sampled evenly rather than by chance.
    const double u = (k + rng.uniform()) / raysPerPoint_;
    const size_t pick = power_.pick(u);
    const int j = emitters_[pick];
    const auto corners = mesh_.corners(j);
    const Eigen::Vector3d centre = (corners[0] + corners[1] + corners[2]) / 3;
    double radius = 0;
    for (const Eigen::Vector3d& c : corners) radius = std::max(radius, (c - centre).norm());
    if ((centre - x).norm() > kFarRadii * radius) {
      // Far from the emitting element: the point estimate E·A·cos·cos/(π r²) of one uniform point
      // y on it, visible or not, is bounded here and unbiased also in a penumbra, where the
      // visible part of the element is not a uniform share of its factor.
      const Eigen::Vector3d y = uniformPointOnTriangle(corners, rng.uniform(), rng.uniform());
      const Eigen::Vector3d d = y - x;
      const double r = d.norm();
      const Eigen::Vector3d w = d / r;
      const double cosines = n.dot(w) * -mesh_.normal(j).dot(w);
      if (n.dot(w) > 0 && cosines > 0 && visible(x, n, y, mesh_.normal(j)))
        sum += emission_[j] * (cosines * mesh_.area(j) / (M_PI * r * r) / power_.probability(pick));
      continue;
    }
    // Near it: the unoccluded factor in closed form, bounded by 1 however near the emitter:
    // E·A·cos·cos/(π r²) at one point of it had no bound beside an emitter (a furnace room of
    // emitting walls: elements at a wall's foot up to 8 times too bright).
    std::copy(corners.begin(), corners.end(), triangle.begin());
    const double factor = pointToPolygonFormFactor(x, n, triangle);
    if (factor <= 0) continue;
    // Visibility by a shadow ray to a point of the emitter that x sees (a few tries: part of the
    // emitter may lie below x's horizon).
    for (int attempt = 0; attempt < kVisibilityAttempts; ++attempt) {
      const Eigen::Vector3d y = uniformPointOnTriangle(corners, rng.uniform(), rng.uniform());
      const Eigen::Vector3d w = (y - x).normalized();
      if (!(n.dot(w) > 0 && mesh_.normal(j).dot(w) < 0)) continue;
      if (visible(x, n, y, mesh_.normal(j)))
        sum += emission_[j] * (factor / power_.probability(pick));
      break;
    }
  }
  return sum / raysPerPoint_;
}

void EmitterFirstShot::restore(RadiosityProblem& problem, std::vector<Rgb>& radiosity) const {
  if (emitters_.empty()) return;
  for (int e = 0; e < problem.size(); ++e) {
    radiosity[e] += emission_[e];
    // What was added after apply() (the lights' first shot) stays.
    problem.emission[e] += emission_[e] - problem.reflectance[e] * irradiance_[e];
  }
}

}  // namespace rad
