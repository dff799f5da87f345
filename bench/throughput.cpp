// Ray throughput of the form-factor rows against raw Embree on the same scene, the same rays
// and the same thread count (issue 8). The rows' rays are traced once up front (traceRow gives
// each ray's origin and direction); the raw benchmark casts exactly those rays with
// rtcIntersect1 on a plain Embree scene of the same triangles built with the same settings as
// RayCaster's (robust, high quality), so the ratio of the two rates is what the form-factor code
// (sampling, hit bookkeeping, row assembly) costs on top of Embree. rawEmbreeDefaultBuild shows
// what Embree's faster, non-robust default build would give on the same rays. ratioInTurn gives
// the ratio from the two taken in turn, for machines shared with other work.
//   throughput [--benchmark_format=json]   (scene: RADIOSITY_BENCH_SCENE, default Cornell box)
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "radiosity/core/log.h"
#include "radiosity/formfactors/hemisphere_form_factors.h"
#include "radiosity/pipeline/mesh_stage.h"
#include "radiosity/scene/scene_loader.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

constexpr int kRaysPerElement = 1024;

struct Setup {
  Scene scene;
  std::unique_ptr<PatchMesh> mesh;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<HemisphereFormFactors> method;
  std::vector<RTCRayHit> rays;  // the rows' rays, in scene coordinates (float)
  RTCDevice device = nullptr;
  RTCScene raw = nullptr;         // built as RayCaster builds its BVH (robust, high quality)
  RTCScene rawDefault = nullptr;  // Embree's default build: what robustness costs, for the record

  Setup() {
    setLogLevel(LogLevel::Quiet);
    const char* path = std::getenv("RADIOSITY_BENCH_SCENE");
    const char* elements = std::getenv("RADIOSITY_BENCH_ELEMENTS");
    scene = loadScene(path ? path : RADIOSITY_DATA_DIR "/cornell_box/cornell_box.obj");
    SolveOptions options;  // the solve's mesh: hemisphere rows, uniform elements
    if (elements) options.targetElements = std::atoi(elements);
    mesh = meshScene(scene, options).mesh;
    caster = std::make_unique<RayCaster>(*mesh);
    // No emitter multipliers: every row has the same ray count, so the rates compare like for like.
    method = std::make_unique<HemisphereFormFactors>(*mesh, *caster,
                                                     HemisphereOptions{kRaysPerElement, 1});
    rays.reserve(size_t(mesh->elementCount()) * kRaysPerElement);
    for (int e = 0; e < mesh->elementCount(); ++e)
      for (const RowRay& r : method->traceRow(e)) {
        RTCRayHit h{};
        h.ray.org_x = float(r.origin.x());
        h.ray.org_y = float(r.origin.y());
        h.ray.org_z = float(r.origin.z());
        h.ray.dir_x = float(r.direction.x());
        h.ray.dir_y = float(r.direction.y());
        h.ray.dir_z = float(r.direction.z());
        rays.push_back(h);
      }
    device = rtcNewDevice(nullptr);
    raw = plainScene(RTC_SCENE_FLAG_ROBUST, RTC_BUILD_QUALITY_HIGH);
    rawDefault = plainScene(RTC_SCENE_FLAG_NONE, RTC_BUILD_QUALITY_MEDIUM);
  }
  // The elements' triangles as a plain Embree scene, with the given flags.
  RTCScene plainScene(RTCSceneFlags flags, RTCBuildQuality quality) {
    RTCScene scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, flags);
    rtcSetSceneBuildQuality(scene, quality);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const int n = mesh->elementCount();
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    for (int e = 0; e < n; ++e) {
      const auto c = mesh->corners(e);
      for (int k = 0; k < 3; ++k) {
        for (int d = 0; d < 3; ++d) v[9 * e + 3 * k + d] = float(c[k][d]);
        idx[3 * e + k] = unsigned(3 * e + k);
      }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
    return scene;
  }
  ~Setup() {
    rtcReleaseScene(raw);
    rtcReleaseScene(rawDefault);
    rtcReleaseDevice(device);
  }
};

Setup& setup() {
  static Setup s;
  return s;
}

// One pass of the form-factor rows: rows in parallel (as gatherMatrix does), each row's rays in
// parallel inside computeRow.
void formFactorPass(const Setup& s) {
  tbb::parallel_for(0, s.mesh->elementCount(),
                    [&](int e) { benchmark::DoNotOptimize(s.method->computeRow(e)); });
}

// One pass of the same rays with rtcIntersect1 (incoherent context, as RayCaster uses).
void rawPass(const Setup& s, RTCScene scene) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, s.rays.size(), 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      RTCIntersectContext context;
                      rtcInitIntersectContext(&context);
                      context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
                      for (size_t k = r.begin(); k != r.end(); ++k) {
                        RTCRayHit h = s.rays[k];
                        h.ray.tnear = 0;
                        h.ray.tfar = std::numeric_limits<float>::infinity();
                        h.ray.mask = ~0u;
                        h.ray.flags = 0;
                        h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(scene, &context, &h);
                        benchmark::DoNotOptimize(h.hit.primID);
                      }
                    });
}

void formFactorRows(benchmark::State& state) {
  Setup& s = setup();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  uint64_t rays = 0;
  for (auto _ : state) {
    formFactorPass(s);
    rays += uint64_t(s.mesh->elementCount()) * kRaysPerElement;
  }
  state.counters["rays_per_s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
  state.counters["elements"] = s.mesh->elementCount();
}

void castRaw(benchmark::State& state, RTCScene scene) {
  Setup& s = setup();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  uint64_t rays = 0;
  for (auto _ : state) {
    rawPass(s, scene);
    rays += s.rays.size();
  }
  state.counters["rays_per_s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
}

// The ratio itself from the two passes taken in turn inside each iteration (form-factor rows,
// then raw Embree on the same rays, wall time each): load from other work on a shared machine
// that drifts over seconds then weighs on both alike, unlike two benchmarks run one after the
// other.
void ratioInTurn(benchmark::State& state) {
  Setup& s = setup();
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  using Clock = std::chrono::steady_clock;
  double formFactorSeconds = 0, rawSeconds = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    formFactorPass(s);
    const auto t1 = Clock::now();
    rawPass(s, s.raw);
    formFactorSeconds += std::chrono::duration<double>(t1 - t0).count();
    rawSeconds += std::chrono::duration<double>(Clock::now() - t1).count();
  }
  state.counters["ratio"] = rawSeconds / formFactorSeconds;
}

// The baseline of the ratio: the same BVH settings as the form factors' RayCaster.
void rawEmbree(benchmark::State& state) { castRaw(state, setup().raw); }
// Embree's default (non-robust, medium-quality) build, reported beside it: not a like-for-like
// baseline (robust traversal is what keeps rays from slipping through shared edges).
void rawEmbreeDefaultBuild(benchmark::State& state) { castRaw(state, setup().rawDefault); }

// 1, 2, 4, … up to the machine's hardware threads, so the same binary measures scaling anywhere.
void threadCounts(benchmark::internal::Benchmark* b) {
  const int most = std::max(1, int(std::thread::hardware_concurrency()));
  for (int t = 1; t < most; t *= 2) b->Arg(t);
  b->Arg(most);
}

BENCHMARK(formFactorRows)
    ->Apply(threadCounts)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(rawEmbree)
    ->Apply(threadCounts)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(rawEmbreeDefaultBuild)
    ->Apply(threadCounts)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(ratioInTurn)
    ->Apply(threadCounts)
    ->ArgName("threads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rad

BENCHMARK_MAIN();
