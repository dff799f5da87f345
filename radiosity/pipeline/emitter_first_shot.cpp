#include "radiosity/pipeline/emitter_first_shot.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/formfactors/point_to_polygon.h"
#include "radiosity/pipeline/exposed_strata.h"

namespace rad {

namespace {
constexpr int kVisibilityAttempts = 4;
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
  double total = 0, emittingArea = 0;
  for (int e = 0; e < problem.size(); ++e) {
    // The emitter's whole area: a buried part of an emitter still emits into its enclosure, where
    // no ray from an exposed receiver reaches it.
    const double power = mesh_.area(e) * problem.emission[e].luminance();
    if (power <= 0) continue;
    if (mesh_.patchArea(mesh_.patch(e)) > largeEmitterShare_ * sceneArea) continue;
    emitters_.push_back(e);
    emittingArea += mesh_.area(e);
    total += power;
    cumulative_.push_back(total);
  }
  if (emittingArea > largeEmitterShare_ * sceneArea) {
    // Many small emitters together: the links' rays find them as often as one large one.
    emitters_.clear();
    cumulative_.clear();
  }
  if (emitters_.empty()) return;
  probability_.resize(emitters_.size());
  for (size_t k = emitters_.size(); k-- > 0;) {  // from the end: each needs its predecessor's sum
    probability_[k] = (cumulative_[k] - (k > 0 ? cumulative_[k - 1] : 0.0)) / total;
    cumulative_[k] /= total;
  }
  cumulative_.back() = 1.0;

  emission_.assign(problem.size(), Rgb());  // E of the emitters shot here; the rest stays
  for (int e : emitters_) emission_[e] = problem.emission[e];
  irradiance_.assign(problem.size(), Rgb());
  std::atomic<uint64_t> cast{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, problem.size(), 64),
                    [&](const tbb::blocked_range<int>& range) {
                      uint64_t local = 0;
                      for (int e = range.begin(); e < range.end(); ++e) {
                        if (problem.reflectance[e].maxComponent() <= 0) continue;
                        const Eigen::Vector3d n = mesh_.normal(e);
                        Rng rng(streamKey(seed_ ^ 0x656d6974746572ull, static_cast<uint64_t>(e)));
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

Rgb EmitterFirstShot::directAt(const Eigen::Vector3d& x, const Eigen::Vector3d& n, Rng& rng) const {
  Rgb sum;
  std::vector<Eigen::Vector3d> triangle(3);
  for (int k = 0; k < raysPerPoint_; ++k) {
    const size_t pick =
        std::min(static_cast<size_t>(
                     std::upper_bound(cumulative_.begin(), cumulative_.end(), rng.uniform()) -
                     cumulative_.begin()),
                 emitters_.size() - 1);
    const int j = emitters_[pick];
    const auto corners = mesh_.corners(j);
    std::copy(corners.begin(), corners.end(), triangle.begin());
    // The unoccluded factor in closed form, bounded by 1 however near the emitter: E·A·cos·cos /
    // (π r²) at one point of it had no bound beside an emitter (a furnace room of emitting walls:
    // elements at a wall's foot up to 8 times too bright).
    const double factor = pointToPolygonFormFactor(x, n, triangle);
    if (factor <= 0) continue;
    // Visibility by a shadow ray to a point of the emitter that x sees (a few tries: part of the
    // emitter may lie below x's horizon).
    for (int attempt = 0; attempt < kVisibilityAttempts; ++attempt) {
      const Eigen::Vector3d y = uniformPointOnTriangle(corners, rng.uniform(), rng.uniform());
      const Eigen::Vector3d d = y - x;
      const double r = d.norm();
      if (!(r > 0)) continue;
      const Eigen::Vector3d w = d / r;
      if (n.dot(w) <= 0 || mesh_.normal(j).dot(w) >= 0) continue;
      // Both ends lifted off their surfaces, towards each other: a ray from the lifted receiver
      // point along x → y alone would meet the emitter's plane before y at grazing angles.
      const Eigen::Vector3d from = rays_.liftOff(x, n, w);
      const Eigen::Vector3d to = rays_.liftOff(y, mesh_.normal(j), -w);
      const Eigen::Vector3d along = to - from;
      const double length = along.norm();
      if (!(length > 0 && rays_.occluded(from, along / length, length)))
        sum += emission_[j] * (factor / probability_[pick]);
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
