// Light probes: the incident radiance at points of a solved scene, projected onto order-2 SH.
#include "radiosity/render/light_probes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "radiosity/core/errors.h"
#include "radiosity/core/rng.h"
#include "radiosity/core/stream_tags.h"
#include "radiosity/lighting/light_sample.h"

namespace rad {
namespace {

// A uniformly random rotation (Shoemake's unit quaternion from three uniforms).
Eigen::Matrix3d randomRotation(Rng& rng) {
  const double u1 = rng.uniform(), u2 = 2 * M_PI * rng.uniform(), u3 = 2 * M_PI * rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const Eigen::Quaterniond q(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3),
                             b * std::cos(u3));
  return q.normalized().toRotationMatrix();
}

// The i-th of n points of the spherical Fibonacci set: equal-area bands in z, golden-angle
// steps in azimuth.
Eigen::Vector3d fibonacciDirection(int i, int n) {
  const double z = 1 - (2 * i + 1) / double(n);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * M_PI * i * 0.6180339887498949;  // i / golden ratio turns
  return {r * std::cos(phi), r * std::sin(phi), z};
}

void addScaled(std::array<Rgb, 9>& c, const std::array<double, 9>& y, const Rgb& value) {
  for (int k = 0; k < 9; ++k) c[k] += value * y[k];
}

ProbeSh computeProbe(const RenderScene& view, const std::vector<Rgb>& radiosity,
                     const Eigen::Vector3d& x, int rays, uint64_t seed, uint64_t index,
                     const ProbeLights& lights) {
  ProbeSh probe;
  probe.position = x;
  Rng rng(streamKey(seed, stream_tag::kProbe, index));
  const Eigen::Matrix3d rotation = randomRotation(rng);
  const double weight = 4 * M_PI / rays;
  int backHits = 0;
  for (int i = 0; i < rays; ++i) {
    const Eigen::Vector3d d = (rotation * fibonacciDirection(i, rays)).normalized();
    bool back = false;
    const Rgb radiance = probeRayRadiance(view, radiosity, lights, x, d, &back);
    backHits += back;
    if (!radiance.isZero()) addScaled(probe.coefficients, shBasis(d), radiance * weight);
  }
  probe.inside = 2 * backHits > rays;
  for (const LightArrival& a : lightArrivals(view, lights, x))
    addScaled(probe.coefficients, shBasis(a.toLight), a.irradiance);
  return probe;
}

void putU32(std::ostream& out, uint32_t v) {
  const unsigned char b[4] = {static_cast<unsigned char>(v), static_cast<unsigned char>(v >> 8),
                              static_cast<unsigned char>(v >> 16),
                              static_cast<unsigned char>(v >> 24)};
  out.write(reinterpret_cast<const char*>(b), 4);
}

void putF32(std::ostream& out, double value) {
  const float f = static_cast<float>(value);
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  putU32(out, bits);
}

uint32_t getU32(const unsigned char* b) {
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

float getF32(const unsigned char* b) {
  const uint32_t bits = getU32(b);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

constexpr char kProbesMagic[] = "RADPRB01";
constexpr size_t kProbesHeader = 12, kProbeBytes = 124;

}  // namespace

std::array<double, 9> shBasis(const Eigen::Vector3d& direction) {
  const double x = direction.x(), y = direction.y(), z = direction.z();
  // Exact constants: 1/(2√π), √(3/(4π)), √(15/π)/2, √(5/π)/4, √(15/π)/4.
  constexpr double c0 = 0.28209479177387814, c1 = 0.4886025119029199, c2 = 1.0925484305920792,
                   c20 = 0.31539156525252005, c22 = 0.5462742152960396;
  return {c0,
          c1 * y,
          c1 * z,
          c1 * x,
          c2 * x * y,
          c2 * y * z,
          c20 * (3 * z * z - 1),
          c2 * x * z,
          c22 * (x * x - y * y)};
}

ProbeLights::ProbeLights(const Scene& scene) {
  for (const Light& light : scene.lights) {
    if (isDeltaLight(light))
      deltas.push_back(&light);
    else if (light.type == LightType::Directional)
      discs.push_back(&light);
    else
      skies.push_back(&light);
  }
}

Rgb probeRayRadiance(const RenderScene& view, const std::vector<Rgb>& radiosity,
                     const ProbeLights& lights, const Eigen::Vector3d& origin,
                     const Eigen::Vector3d& direction, bool* backFace) {
  const SurfaceHit hit = view.intersect(origin, direction);
  Rgb radiance;
  if (hit.hit()) {
    if (hit.front)
      radiance = radiosity.at(hit.element) / M_PI;
    else if (backFace)
      *backFace = true;
  } else {
    for (const Light* sky : lights.skies) radiance += radianceAlong(*sky, direction);
  }
  return radiance;
}

std::vector<LightArrival> lightArrivals(const RenderScene& view, const ProbeLights& lights,
                                        const Eigen::Vector3d& x) {
  std::vector<LightArrival> arrivals;
  const auto arrive = [&](const LightSample& s, const Rgb& irradiance) {
    if (irradiance.isZero()) return;
    const bool blocked = std::isfinite(s.distance) ? view.occluded(x, x + s.direction * s.distance)
                                                   : view.occludedAlong(x, s.direction);
    if (!blocked) arrivals.push_back({s.direction, irradiance});
  };
  for (const Light* light : lights.deltas) {
    const LightSample s = sampleLight(*light, x, -light->direction, 0, 0);
    arrive(s, s.radiance);  // E⊥: a probe has no surface of its own
  }
  // A sun's disc by the centres of kDiscStrata² equal strata of it, each its share of E⊥.
  constexpr int kDiscStrata = 4;
  for (const Light* light : lights.discs)
    for (int k = 0; k < kDiscStrata * kDiscStrata; ++k) {
      const LightSample s =
          sampleLight(*light, x, -light->direction, (k % kDiscStrata + 0.5) / kDiscStrata,
                      (k / kDiscStrata + 0.5) / kDiscStrata);
      arrive(s, s.radiance / (s.pdf * kDiscStrata * kDiscStrata));
    }
  return arrivals;
}

std::vector<ProbeSh> computeProbes(const RenderScene& view, const std::vector<Rgb>& radiosity,
                                   const std::vector<Eigen::Vector3d>& points, int rays,
                                   uint64_t seed) {
  if (rays < 1) throw InputError("light probes need at least one ray each");
  // Lights at infinity seen by the escaped rays, and those added analytically.
  const ProbeLights lights(view.scene());
  std::vector<ProbeSh> probes(points.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size()),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t p = range.begin(); p < range.end(); ++p)
                        probes[p] = computeProbe(view, radiosity, points[p], rays, seed, p, lights);
                    });
  return probes;
}

Rgb probeIrradiance(const ProbeSh& probe, const Eigen::Vector3d& normal) {
  static const double kBand[9] = {M_PI,     2 * M_PI / 3, 2 * M_PI / 3, 2 * M_PI / 3, M_PI / 4,
                                  M_PI / 4, M_PI / 4,     M_PI / 4,     M_PI / 4};
  const std::array<double, 9> y = shBasis(normal.normalized());
  Rgb e;
  for (int k = 0; k < 9; ++k) e += probe.coefficients[k] * (kBand[k] * y[k]);
  return e;
}

std::vector<Eigen::Vector3d> probeGrid(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                       double spacing) {
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw InputError("the probe spacing must be a positive number of scene units");
  if (!lo.allFinite() || !hi.allFinite() || (hi - lo).minCoeff() < 0)
    throw InputError("the probe grid's box is empty or not finite");
  Eigen::Vector3d start;
  int n[3];
  double total = 1;
  for (int a = 0; a < 3; ++a) {
    const double extent = hi[a] - lo[a];
    const double count = std::floor(extent / spacing) + 1;
    total *= count;
    if (!(total <= 1e6))
      throw InputError("the probe grid would exceed 1,000,000 points: use a larger spacing");
    n[a] = static_cast<int>(count);
    start[a] = lo[a] + 0.5 * (extent - (n[a] - 1) * spacing);
  }
  std::vector<Eigen::Vector3d> points;
  points.reserve(static_cast<size_t>(total));
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) points.push_back(start + spacing * Eigen::Vector3d(i, j, k));
  return points;
}

void writeProbesJson(std::ostream& out, const std::vector<ProbeSh>& probes) {
  nlohmann::json list = nlohmann::json::array();
  for (const ProbeSh& p : probes) {
    nlohmann::json sh = nlohmann::json::array();
    for (const Rgb& c : p.coefficients) sh.push_back({c.r, c.g, c.b});
    list.push_back({{"position", {p.position.x(), p.position.y(), p.position.z()}},
                    {"inside", p.inside},
                    {"sh", sh}});
  }
  const nlohmann::json doc = {
      {"convention",
       "real spherical harmonics l <= 2, Sloan 'Stupid SH Tricks' normalisation, index k = "
       "l(l+1)+m, (x, y, z) the direction in the scene frame (+y up): Y00 = 0.282095, Y1-1 = "
       "0.488603 y, Y10 = 0.488603 z, Y11 = 0.488603 x, Y2-2 = 1.092548 xy, Y2-1 = 1.092548 yz, "
       "Y20 = 0.315392 (3z^2 - 1), Y21 = 1.092548 xz, Y22 = 0.546274 (x^2 - y^2); c_k = "
       "integral of L(w) Y_k(w) dw; irradiance E(n) = sum A_l c_k Y_k(n), A_0 = pi, A_1 = 2pi/3, "
       "A_2 = pi/4"},
      {"unit", "W/m^2 (coefficients of radiance in W/(m^2 sr) over the sphere)"},
      {"probes", list}};
  out << doc.dump(1) << "\n";
}

void writeProbesBinary(std::ostream& out, const std::vector<ProbeSh>& probes) {
  out.write(kProbesMagic, 8);
  putU32(out, static_cast<uint32_t>(probes.size()));
  for (const ProbeSh& p : probes) {
    for (int a = 0; a < 3; ++a) putF32(out, p.position[a]);
    for (const Rgb& c : p.coefficients)
      for (int ch = 0; ch < 3; ++ch) putF32(out, c[ch]);
    putU32(out, p.inside ? 1u : 0u);
  }
}

std::vector<ProbeSh> readProbesBinary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the light probes");
  auto fail = [&](const std::string& what) { throw InputError(path, 0, what); };
  unsigned char header[kProbesHeader];
  in.read(reinterpret_cast<char*>(header), kProbesHeader);
  const size_t got = static_cast<size_t>(in.gcount());
  if (got == 0) fail("empty: not a light probes file");
  if (std::memcmp(header, kProbesMagic, std::min<size_t>(got, 8)) != 0)
    fail("not a light probes file (it starts with \"RADPRB01\")");
  if (got < kProbesHeader)
    fail("cut short in the header (" + std::to_string(got) + " of 12 bytes)");
  const uint32_t count = getU32(header + 8);
  if (count > kMaxProbes)
    fail(std::to_string(count) + " probes: more than a probe grid holds (" +
         std::to_string(kMaxProbes) + ")");
  // The length against the count before anything is allocated for the probes.
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if (end < 0) fail("cannot read the file's length");
  const uint64_t expected = kProbesHeader + uint64_t(kProbeBytes) * count;
  const uint64_t length = static_cast<uint64_t>(end);
  if (length != expected)
    fail(std::string(length < expected ? "cut short" : "longer than its count says") + ": " +
         std::to_string(count) + " probes take " + std::to_string(expected) +
         " bytes, the file has " + std::to_string(length));
  in.seekg(static_cast<std::streamoff>(kProbesHeader));
  std::vector<unsigned char> bytes(expected - kProbesHeader);
  if (!bytes.empty()) {
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!in || static_cast<size_t>(in.gcount()) != bytes.size()) fail("cannot read the probes");
  }
  std::vector<ProbeSh> probes(count);
  for (uint32_t i = 0; i < count; ++i) {
    const unsigned char* b = bytes.data() + size_t(i) * kProbeBytes;
    const std::string which = "probe " + std::to_string(i);
    ProbeSh& p = probes[i];
    for (int a = 0; a < 3; ++a) p.position[a] = getF32(b + 4 * a);
    if (!p.position.allFinite()) fail(which + ": its position is not finite");
    for (int k = 0; k < 9; ++k)
      for (int ch = 0; ch < 3; ++ch) p.coefficients[k][ch] = getF32(b + 12 + 4 * (3 * k + ch));
    for (const Rgb& c : p.coefficients)
      if (!c.isFinite()) fail(which + ": a coefficient is not finite");
    const uint32_t flags = getU32(b + 120);
    if (flags > 1) fail(which + ": unknown flags " + std::to_string(flags) + " (bit 0: inside)");
    p.inside = flags & 1u;
  }
  return probes;
}

}  // namespace rad
