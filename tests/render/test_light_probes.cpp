// Light probes (render/light_probes.h): the SH basis against its own orthonormality, and probes
// against closed-form projections: a furnace (every element the same B, so L = B/π from every
// direction), a uniform sky over an empty scene, a lone directional light; the grid and the
// binary layout, and its reader (round trip, every truncation and corruption refused or read
// whole).
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/render/light_probes.h"
#include "radiosity/visibility/ray_caster.h"

namespace rad {
namespace {

// The unit cube's six faces, looking inward (or outward), split to at most `maxArea`.
PatchMesh cube(double maxArea, bool inward = true) {
  std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<PatchPolygon> faces = {{{0, 1, 2, 3}, 0}, {{4, 7, 6, 5}, 0}, {{0, 4, 5, 1}, 0},
                                     {{3, 2, 6, 7}, 0}, {{0, 3, 7, 4}, 0}, {{1, 5, 6, 2}, 0}};
  if (!inward)
    for (auto& f : faces) std::reverse(f.vertices.begin(), f.vertices.end());
  PatchMesh mesh(p, faces);
  mesh.subdivideUniform(maxArea);
  return mesh;
}

// A 1 cm quad 1000 units below the origin, facing down: a scene no probe ray near the origin
// meets (its solid angle from there is 1e-10 sr).
PatchMesh farQuad() {
  return PatchMesh({{0, -1000, 0}, {0.01, -1000, 0}, {0.01, -1000, 0.01}, {0, -1000, 0.01}},
                   {{{0, 1, 2, 3}, 0}});
}

Scene sceneWith(const std::vector<Light>& lights) {
  Scene scene;
  scene.sourcePath = "test";
  Material grey;
  grey.name = "grey";
  grey.diffuse = {0.5, 0.5, 0.5};
  scene.materials.push_back(grey);
  scene.lights = lights;
  return scene;
}

struct View {
  Scene scene;
  PatchMesh mesh;
  std::unique_ptr<RayCaster> caster;
  std::unique_ptr<RenderScene> view;
  View(Scene s, PatchMesh m) : scene(std::move(s)), mesh(std::move(m)) {
    caster = std::make_unique<RayCaster>(mesh);
    view = std::make_unique<RenderScene>(scene, mesh, *caster);
  }
};

// ∫ f(ω) dω over the sphere by the midpoint rule in (cos θ, φ): equal-area cells.
template <typename F>
void integrateSphere(int n, F&& f) {
  const double dz = 2.0 / n, dphi = 2 * M_PI / (2 * n), dw = dz * dphi;
  for (int i = 0; i < n; ++i) {
    const double z = -1 + (i + 0.5) * dz, r = std::sqrt(1 - z * z);
    for (int j = 0; j < 2 * n; ++j) {
      const double phi = (j + 0.5) * dphi;
      f(Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z), dw);
    }
  }
}

TEST(LightProbes, ShBasisIsOrthonormalOverTheSphere) {
  double gram[9][9] = {};
  integrateSphere(400, [&](const Eigen::Vector3d& w, double dw) {
    const auto y = shBasis(w);
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) gram[i][j] += y[i] * y[j] * dw;
  });
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) EXPECT_NEAR(gram[i][j], i == j ? 1.0 : 0.0, 1e-3) << i << "," << j;
  // The documented convention: Y1,-1 ∝ y (up), Y1,0 ∝ z, Y1,1 ∝ x.
  EXPECT_GT(shBasis({0, 1, 0})[1], 0.48);
  EXPECT_GT(shBasis({0, 0, 1})[2], 0.48);
  EXPECT_GT(shBasis({1, 0, 0})[3], 0.48);
}

// Every element at B: every ray sees B/π, so c_0 = 4π · Y00 · B/π = 2√π B/π for any direction
// set. The higher coefficients are the set's quadrature of ∫ Y_k = 0: the spherical Fibonacci set
// integrates low-order polynomials to O(1/N) (and Y_k, k ≥ 1 are odd or zero-mean), so far below
// 1% of c_0 with 1024 rays. The irradiance from them is then B at any normal.
TEST(LightProbes, FurnaceGivesTheExactDcTermAndIrradianceB) {
  View v(sceneWith({}), cube(0.02));
  const Rgb b{1.0, 2.0, 0.5};
  const std::vector<Rgb> radiosity(v.mesh.elementCount(), b);
  const std::vector<Eigen::Vector3d> points = {
      {0.5, 0.5, 0.5}, {0.2, 0.3, 0.7}, {0.9, 0.1, 0.4}, {0.05, 0.95, 0.5}};
  const auto probes = computeProbes(*v.view, radiosity, points, 1024, 7);
  ASSERT_EQ(probes.size(), points.size());
  for (const ProbeSh& p : probes) {
    EXPECT_FALSE(p.inside);
    for (int ch = 0; ch < 3; ++ch) {
      const double c0 = 2 * std::sqrt(M_PI) * b[ch] / M_PI;
      EXPECT_NEAR(p.coefficients[0][ch], c0, 1e-6 * c0);
      for (int k = 1; k < 9; ++k) EXPECT_LT(std::abs(p.coefficients[k][ch]), 1e-2 * c0) << k;
    }
    for (const Eigen::Vector3d& n : {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0),
                                     Eigen::Vector3d(0.3, -0.5, 0.8).normalized()}) {
      const Rgb e = probeIrradiance(p, n);
      for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(e[ch], b[ch], 0.01 * b[ch]);
    }
  }
}

// Inside a cube whose faces look outward every ray meets a back face: flagged, and it sees 0.
TEST(LightProbes, ProbeInsideGeometryIsFlagged) {
  View v(sceneWith({}), cube(0.05, /*inward=*/false));
  const std::vector<Rgb> radiosity(v.mesh.elementCount(), Rgb{1, 1, 1});
  const auto probes = computeProbes(*v.view, radiosity, {{0.5, 0.5, 0.5}, {3, 0.5, 0.5}}, 256, 1);
  EXPECT_TRUE(probes[0].inside);
  EXPECT_EQ(probes[0].coefficients[0].r, 0.0);
  EXPECT_FALSE(probes[1].inside);  // outside it sees the front faces
  EXPECT_GT(probes[1].coefficients[0].r, 0.0);
}

// A uniform sky of radiance Ls above the horizon (y > 0), black below, nothing in the way: the
// projection of Ls·[y > 0], computed here by a fine quadrature (c_0 = √π Ls, c_1 = √(3/(4π)) π Ls,
// the rest 0). The Fibonacci set integrates the step at the horizon with an error of the order of
// the band it cuts, ~1/√N of the sphere's edge length: 2% of c_0 at 1024 rays is ample.
TEST(LightProbes, UniformSkyIsTheUpperHemisphereProjection) {
  Light sky;
  sky.type = LightType::Sky;
  sky.radiance = {1, 2, 3};
  View v(sceneWith({sky}), farQuad());
  const std::vector<Rgb> radiosity(v.mesh.elementCount(), Rgb{5, 5, 5});
  std::array<double, 9> expected{};
  integrateSphere(800, [&](const Eigen::Vector3d& w, double dw) {
    if (w.y() <= 0) return;
    const auto y = shBasis(w);
    for (int k = 0; k < 9; ++k) expected[k] += y[k] * dw;
  });
  EXPECT_NEAR(expected[0], std::sqrt(M_PI), 1e-4);
  EXPECT_NEAR(expected[1], std::sqrt(3 / (4 * M_PI)) * M_PI, 1e-4);
  const auto probes =
      computeProbes(*v.view, radiosity, {{0, 0, 0}, {1, 2, -3}, {-0.5, 0.1, 0.2}}, 1024, 3);
  for (const ProbeSh& p : probes)
    for (int ch = 0; ch < 3; ++ch) {
      const double ls = sky.radiance[ch];
      for (int k = 0; k < 9; ++k)
        EXPECT_NEAR(p.coefficients[k][ch], expected[k] * ls, 0.02 * std::sqrt(M_PI) * ls)
            << "k " << k << " channel " << ch;
      // Facing up: the sky's irradiance π Ls (the order-2 fit is within a few per cent of it).
      EXPECT_NEAR(probeIrradiance(p, {0, 1, 0})[ch], M_PI * ls, 0.05 * M_PI * ls);
    }
}

// A sun alone: a delta light, added analytically: c_k = E · Y_k(towards the sun) to rounding; and
// nothing under a roof that shadows it.
// A sun's disc is the same disc for the probes as for the solve and the renders: its coefficients
// are c_k = ∫_disc L Y_k dω, L = E / (π sin²h). Y_k is a polynomial of degree ≤ 2 in the direction
// and, uniform in solid angle, cos α to the disc's axis is uniform on [cos h, 1]: the probe's
// 4 × 4 strata centres integrate degree 1 exactly and degree 2 within (Δcos)² ≈ 1e-11 of E; so
// does the independent 400 × 64 midpoint grid here, whence 1e-9.
TEST(LightProbes, SunDiscIsItsRadianceIntegratedOverTheBasis) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = Eigen::Vector3d(0.3, -1, 0.2).normalized();
  sun.irradiance = {3, 2, 1};
  sun.angularDiameterDegrees = 0.53;
  // A roof over x, z in [10, 11] at y = 5, facing down.
  PatchMesh roof({{10, 5, 10}, {11, 5, 10}, {11, 5, 11}, {10, 5, 11}}, {{{0, 1, 2, 3}, 0}});
  View v(sceneWith({sun}), std::move(roof));
  const std::vector<Rgb> radiosity(v.mesh.elementCount(), Rgb{});
  const auto probes = computeProbes(*v.view, radiosity, {{0, 0, 0}, {10.5, 4, 10.5}}, 256, 5);
  // The disc's integral of each Y_k, by its own grid in (cos α, φ) about the axis.
  const Eigen::Vector3d axis = -sun.direction;
  const Eigen::Vector3d t = axis.unitOrthogonal(), b = axis.cross(t);
  const double h = 0.53 / 2 * M_PI / 180, omega = 2 * M_PI * (1 - std::cos(h));
  const int rings = 400, turns = 64;
  std::array<double, 9> meanY{};
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < turns; ++j) {
      const double c = 1 - (i + 0.5) / rings * (1 - std::cos(h)), sn = std::sqrt(1 - c * c);
      const double phi = 2 * M_PI * (j + 0.5) / turns;
      const auto y = shBasis(c * axis + sn * (std::cos(phi) * t + std::sin(phi) * b));
      for (int k = 0; k < 9; ++k) meanY[k] += y[k] / (rings * turns);
    }
  const double radiance = 1 / (M_PI * std::sin(h) * std::sin(h));  // per unit of E
  for (int k = 0; k < 9; ++k)
    for (int ch = 0; ch < 3; ++ch) {
      EXPECT_NEAR(probes[0].coefficients[k][ch], sun.irradiance[ch] * radiance * omega * meanY[k],
                  1e-9)
          << k;
      EXPECT_EQ(probes[1].coefficients[k][ch], 0.0) << k;  // in the roof's shadow
    }
}

TEST(LightProbes, ProbeGridCountsAndCentring) {
  const auto g = probeGrid({0, 0, 0}, {1, 0.5, 0.25}, 0.3);
  // floor(1/0.3)+1 = 4, floor(0.5/0.3)+1 = 2, floor(0.25/0.3)+1 = 1.
  ASSERT_EQ(g.size(), 4u * 2u * 1u);
  Eigen::Vector3d lo = g[0], hi = g[0];
  for (const auto& p : g) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_NEAR(lo.x(), 0.05, 1e-12);
  EXPECT_NEAR(hi.x(), 0.95, 1e-12);
  EXPECT_NEAR(lo.y(), 0.1, 1e-12);
  EXPECT_NEAR(hi.y(), 0.4, 1e-12);
  EXPECT_NEAR(lo.z(), 0.125, 1e-12);
  EXPECT_NEAR(hi.z(), 0.125, 1e-12);
  EXPECT_EQ(probeGrid({0, 0, 0}, {0, 0, 0}, 1).size(), 1u);
  EXPECT_THROW(probeGrid({0, 0, 0}, {1, 1, 1}, 0), InputError);
  EXPECT_THROW(probeGrid({0, 0, 0}, {1, 1, 1}, -1), InputError);
  EXPECT_THROW(probeGrid({0, 0, 0}, {1, 1, 1}, std::numeric_limits<double>::quiet_NaN()),
               InputError);
  EXPECT_THROW(probeGrid({0, 0, 0}, {1, 1, 1}, std::numeric_limits<double>::infinity()),
               InputError);
  EXPECT_THROW(probeGrid({0, 0, 0}, {1, 1, 1}, 0.001), InputError);   // 1001³ points
  EXPECT_EQ(probeGrid({0, 0, 0}, {99, 99, 99}, 1).size(), 1000000u);  // exactly the limit
}

uint32_t readU32(const std::string& s, size_t at) {
  const auto* b = reinterpret_cast<const unsigned char*>(s.data() + at);
  return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}

float readF32(const std::string& s, size_t at) {
  const uint32_t bits = readU32(s, at);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

TEST(LightProbes, BinaryFileFollowsTheDocumentedLayout) {
  std::vector<ProbeSh> probes(2);
  probes[0].position = {1.5, -2, 3};
  probes[1].position = {0, 0.25, 7};
  probes[1].inside = true;
  for (int p = 0; p < 2; ++p)
    for (int k = 0; k < 9; ++k) probes[p].coefficients[k] = {p + 0.5 * k, -1.0 * k, 0.125 * k};
  std::ostringstream out;
  writeProbesBinary(out, probes);
  const std::string s = out.str();
  ASSERT_EQ(s.size(), 12u + 2u * (12u + 108u + 4u));
  EXPECT_EQ(s.substr(0, 8), "RADPRB01");
  EXPECT_EQ(readU32(s, 8), 2u);
  for (int p = 0; p < 2; ++p) {
    const size_t base = 12 + p * 124;
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(readF32(s, base + 4 * a), static_cast<float>(probes[p].position[a]));
    for (int k = 0; k < 9; ++k)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_EQ(readF32(s, base + 12 + 4 * (3 * k + ch)),
                  static_cast<float>(probes[p].coefficients[k][ch]));
    EXPECT_EQ(readU32(s, base + 120), p == 1 ? 1u : 0u);
  }
  std::ostringstream json;
  writeProbesJson(json, probes);
  EXPECT_NE(json.str().find("\"sh\""), std::string::npos);
}

// Three probes with distinct values in every field, exactly representable as f32.
std::vector<ProbeSh> sampleProbes() {
  std::vector<ProbeSh> probes(3);
  for (int p = 0; p < 3; ++p) {
    probes[p].position = {0.5 * p, -2.0 + p, 3.25};
    for (int k = 0; k < 9; ++k) probes[p].coefficients[k] = {p + 0.5 * k, -1.0 * k, 0.125 * k};
  }
  probes[1].inside = true;
  return probes;
}

std::string binaryOf(const std::vector<ProbeSh>& probes) {
  std::ostringstream out;
  writeProbesBinary(out, probes);
  return out.str();
}

std::filesystem::path scratchFile(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("radiosity_test_" + std::to_string(::getpid()) + "_" + name);
}

// Writes `bytes` to a scratch file and reads it back.
struct ProbeFile {
  std::filesystem::path path = scratchFile("probes.bin");
  explicit ProbeFile(const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }
  ~ProbeFile() { std::filesystem::remove(path); }
  std::vector<ProbeSh> read() const { return readProbesBinary(path.string()); }
  // The InputError's message; "" when the file is read.
  std::string error() const {
    try {
      read();
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path.string()) << e.what();
      return e.what();
    }
    return "";
  }
};

TEST(LightProbes, BinaryReaderReadsBackWhatTheWriterWrote) {
  const std::vector<ProbeSh> probes = sampleProbes();
  const std::vector<ProbeSh> back = ProbeFile(binaryOf(probes)).read();
  ASSERT_EQ(back.size(), probes.size());
  for (size_t p = 0; p < probes.size(); ++p) {
    EXPECT_EQ(back[p].position, probes[p].position) << p;
    EXPECT_EQ(back[p].inside, probes[p].inside) << p;
    for (int k = 0; k < 9; ++k)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_EQ(back[p].coefficients[k][ch], probes[p].coefficients[k][ch]) << p << " " << k;
  }
  // Values that are not f32 come back rounded to f32, as the layout stores them.
  std::vector<ProbeSh> one(1);
  one[0].position = {0.1, 0.2, 0.3};
  one[0].coefficients[4] = {1.0 / 3, 2.0 / 3, 1e-9};
  const ProbeSh again = ProbeFile(binaryOf(one)).read().at(0);
  EXPECT_EQ(again.position.x(), double(0.1f));
  EXPECT_EQ(again.coefficients[4].g, double(float(2.0 / 3)));
  EXPECT_TRUE(ProbeFile(binaryOf({})).read().empty());  // no probes: 12 bytes
}

TEST(LightProbes, BinaryReaderRefusesBadFilesNamingTheFileAndWhatIsWrong) {
  const std::string good = binaryOf(sampleProbes());
  auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };
  EXPECT_TRUE(contains(ProbeFile("").error(), "empty"));
  {
    std::string bad = good;
    bad[3] = 'x';
    EXPECT_TRUE(contains(ProbeFile(bad).error(), "not a light probes file"));
  }
  EXPECT_TRUE(contains(ProbeFile("solution.vtp follows").error(), "not a light probes file"));
  // Every truncation is refused: in the header, or against the count.
  for (size_t n = 0; n < good.size(); ++n) {
    const std::string message = ProbeFile(good.substr(0, n)).error();
    EXPECT_TRUE(n == 0 ? contains(message, "empty") : contains(message, "cut short"))
        << n << ": " << message;
  }
  EXPECT_TRUE(contains(ProbeFile(good + "x").error(), "longer than its count says"));
  {
    std::string bad = good;
    bad[8] = 2;  // the count says 2, the file holds 3
    EXPECT_TRUE(contains(ProbeFile(bad).error(), "longer than its count says"));
    bad[8] = 4;
    EXPECT_TRUE(contains(ProbeFile(bad).error(), "cut short"));
  }
  {
    // A count past the limit is refused before anything is allocated.
    std::string bad = good.substr(0, 12);
    bad[8] = bad[9] = bad[10] = bad[11] = '\xff';
    EXPECT_TRUE(contains(ProbeFile(bad).error(), "more than a probe grid holds"));
  }
  auto withF32 = [&](size_t offset, float value) {
    std::string bad = good;
    std::memcpy(&bad[offset], &value, 4);  // the host is little-endian, as the layout
    return bad;
  };
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(contains(ProbeFile(withF32(12 + 124 + 4, nan)).error(),
                       "probe 1: its position is not finite"));
  EXPECT_TRUE(contains(ProbeFile(withF32(12 + 248 + 12 + 4 * 26, -inf)).error(),
                       "probe 2: a coefficient is not finite"));
  {
    std::string bad = good;
    bad[12 + 120] = 2;  // an unknown flag bit
    EXPECT_TRUE(contains(ProbeFile(bad).error(), "probe 0: unknown flags 2"));
  }
  EXPECT_THROW(readProbesBinary(scratchFile("missing.bin").string()), InputError);
}

// Any one byte corrupted: the file is refused with an InputError naming it, or read whole with
// finite values (a corrupted value is still a value).
TEST(LightProbes, BinaryReaderReadsEveryCorruptedByteWholeOrNotAtAll) {
  const std::string good = binaryOf(sampleProbes());
  for (size_t i = 0; i < good.size(); ++i)
    for (const unsigned char value : {0x00, 0x7f, 0x80, 0xff}) {
      std::string bad = good;
      bad[i] = static_cast<char>(value);
      const ProbeFile file(bad);
      try {
        const std::vector<ProbeSh> probes = file.read();
        ASSERT_EQ(probes.size(), 3u) << i;
        for (const ProbeSh& p : probes) {
          EXPECT_TRUE(p.position.allFinite()) << i;
          for (const Rgb& c : p.coefficients) EXPECT_TRUE(c.isFinite()) << i;
        }
      } catch (const InputError& e) {
        EXPECT_EQ(e.file(), file.path.string()) << i;
      }
    }
}

}  // namespace
}  // namespace rad
