#include "radiosity/pipeline/emitter_first_shot.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "radiosity/core/check.h"
#include "radiosity/formfactors/hemisphere_sampling.h"
#include "radiosity/pipeline/direct_light_stage.h"

namespace rad {

EmitterFirstShot::EmitterFirstShot(const PatchMesh& mesh, const RayCaster& rays,
                                   const ElementExposure& exposure, uint64_t seed,
                                   int raysPerElement)
    : mesh_(mesh),
      rays_(rays),
      exposure_(exposure),
      seed_(seed),
      raysPerPoint_(std::max(1, raysPerElement / (kAreaStrata * kAreaStrata))) {}

void EmitterFirstShot::apply(RadiosityProblem& problem) {
  RAD_CHECK(problem.size() == mesh_.elementCount());
  double total = 0;
  for (int e = 0; e < problem.size(); ++e) {
    // The emitter's whole area: a buried part of an emitter still emits into its enclosure, where
    // no ray from an exposed receiver reaches it.
    const double power = mesh_.area(e) * problem.emission[e].luminance();
    if (power <= 0) continue;
    emitters_.push_back(e);
    total += power;
    cumulative_.push_back(total);
  }
  if (emitters_.empty()) return;
  probability_.resize(emitters_.size());
  for (size_t k = emitters_.size(); k-- > 0;) {  // from the end: each needs its predecessor's sum
    probability_[k] = (cumulative_[k] - (k > 0 ? cumulative_[k - 1] : 0.0)) / total;
    cumulative_[k] /= total;
  }
  cumulative_.back() = 1.0;

  emission_ = problem.emission;
  irradiance_.assign(problem.size(), Rgb());
  std::atomic<uint64_t> cast{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, problem.size(), 64),
                    [&](const tbb::blocked_range<int>& range) {
                      uint64_t local = 0;
                      for (int e = range.begin(); e < range.end(); ++e) {
                        if (problem.reflectance[e].maxComponent() <= 0) continue;
                        const Eigen::Vector3d n = mesh_.normal(e);
                        const auto corners = mesh_.corners(e);
                        const bool partlyBuried = exposure_.buriedCells(e) != 0;
                        Rng rng(streamKey(seed_ ^ 0x656d6974746572ull, static_cast<uint64_t>(e)));
                        Rgb sum;
                        int used = 0;
                        for (int j = 0; j < kAreaStrata * kAreaStrata; ++j) {
                          const double s = (j % kAreaStrata + rng.uniform()) / kAreaStrata;
                          const double t = (j / kAreaStrata + rng.uniform()) / kAreaStrata;
                          if (partlyBuried && exposure_.buried(e, s, t)) continue;
                          sum += directAt(uniformPointOnTriangle(corners, s, t), n, rng, emission_);
                          local += raysPerPoint_;
                          ++used;
                        }
                        irradiance_[e] = used > 0 ? sum / used : Rgb();
                      }
                      cast += local;
                    });
  raysCast_ = cast;
  for (int e = 0; e < problem.size(); ++e)
    problem.emission[e] = problem.reflectance[e] * irradiance_[e];
}

Rgb EmitterFirstShot::directAt(const Eigen::Vector3d& x, const Eigen::Vector3d& n, Rng& rng,
                               const std::vector<Rgb>& emission) const {
  Rgb sum;
  for (int k = 0; k < raysPerPoint_; ++k) {
    const size_t pick =
        std::min(static_cast<size_t>(
                     std::upper_bound(cumulative_.begin(), cumulative_.end(), rng.uniform()) -
                     cumulative_.begin()),
                 emitters_.size() - 1);
    const int j = emitters_[pick];
    const Eigen::Vector3d y =
        uniformPointOnTriangle(mesh_.corners(j), rng.uniform(), rng.uniform());
    const Eigen::Vector3d d = y - x;
    const double r2 = d.squaredNorm();
    if (r2 <= 0) continue;
    const double r = std::sqrt(r2);
    const Eigen::Vector3d w = d / r;
    const double cosReceiver = n.dot(w), cosEmitter = -mesh_.normal(j).dot(w);
    if (cosReceiver <= 0 || cosEmitter <= 0) continue;
    // Both ends lifted off their surfaces, towards each other: a ray from the lifted receiver
    // point along x → y alone would meet the emitter's plane before y at grazing angles.
    const Eigen::Vector3d from = rays_.liftOff(x, n, w);
    const Eigen::Vector3d to = rays_.liftOff(y, mesh_.normal(j), -w);
    const Eigen::Vector3d along = to - from;
    const double length = along.norm();
    if (length > 0 && rays_.occluded(from, along / length, length)) continue;
    // L = E/π towards x; the point's density is probability / area.
    sum +=
        emission[j] * (cosReceiver * cosEmitter / (M_PI * r2) * mesh_.area(j) / probability_[pick]);
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
