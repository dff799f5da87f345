// factors.bin (radiosity/pipeline/kept_factors.h), what `solve --keep-factors` keeps for
// `relight`: what writeKeptFactors writes, readKeptFactors reads back (values as the file holds
// them: rows in float), and every file cut short, patched or padded is an InputError naming the
// file, never a crash or another exception.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/kept_factors.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMagicBytes = 25;  // "radiosity kept factors 2\n"

// 4 elements, 2 lights; row 0 plain, row 1 tinted, row 2 empty (all escaped), row 3 plain with
// values a float does not hold exactly.
// Four rows: three targets, two tinted targets, none, three (values that are no float).
std::vector<FormFactorRow> sampleRows() {
  std::vector<FormFactorRow> rows(4);
  rows[0].targets = {1, 2, 3};
  rows[0].values = {0.25, 0.125, 0.3};
  rows[0].escaped = 0.325;
  rows[1].targets = {0, 3};
  rows[1].values = {0.5, 0.2};
  rows[1].tinted = {{0.5, 0.4, 0.3}, {0.2, 0.1, 0.05}};
  rows[1].escaped = 0.3;
  rows[2].escaped = 1;
  rows[3].targets = {0, 1, 2};
  rows[3].values = {0.1, 0.2, 0.3};
  rows[3].escaped = 0.4;
  return rows;
}

KeptFactors sample() {
  KeptFactors k;
  k.scenePath = "scene.obj";
  k.fingerprint = "abc";
  k.options.targetElements = 4;
  k.options.raysPerElement = 64;
  k.options.seed = 7;
  k.options.solver = SolverKind::GaussSeidel;
  k.options.tolerance = 1e-5;
  k.options.maxIterations = 50;
  k.options.twoSided.materials = {"glass"};
  k.options.keepFactors = true;
  k.area = {0.5, 0.25, 1.0 / 3, 2.0};
  k.lightGroups = {"lamp", "sun"};
  k.lightTypes = {"spot", "directional"};
  k.lightIrradiance = {{{1, 2, 3}, {0.1, 0.2, 0.3}, {0, 0, 0}, {4, 5, 6}},
                       {{0, 0, 0}, {7, 7, 7}, {1.0 / 7, 2, 3}, {0.5, 0, 0.25}}};
  k.rows = KeptRowTable(sampleRows());
  k.elementEdge = 0.125;
  k.lightInput.file = "lamps.lights.json";
  k.lightsFingerprint = "1f2e3d4c5b6a7980";
  k.materialVisibility = {{"white", "0123456789abcdef"}, {"glass pane", "fedcba9876543210"}};
  k.lightInput.shortcuts = {skyLight({0.3, 0.4, 0.5}), sunLight({0.3, -1, 0.25}, {8, 7, 6})};
  for (int e = 0; e < 4; ++e) {
    k.corners.push_back(
        {Eigen::Vector3d(e, 0, 0), Eigen::Vector3d(e, 1, 0.5), Eigen::Vector3d(e, 0, 1.0 / 3)});
    k.material.push_back(e % 2);
    k.patch.push_back(e / 2);
    k.rayMultiplier.push_back(1 + 21 * e);
  }
  return k;
}

std::string bytesOf(const KeptFactors& kept) {
  std::ostringstream out(std::ios::binary);
  writeKeptFactors(out, kept);
  return out.str();
}

// Where the parts of sample()'s file start (the layout documented in kept_factors.h).
struct Layout {
  size_t headerBytes = 0, header = 0, area = 0, irradiance = 0, rows = 0;
  size_t row(int i) const {
    const KeptFactors k = sample();
    size_t at = rows;
    for (int r = 0; r < i; ++r) {
      const size_t c = k.rows.row(r).targets.size();
      at += 4 + 1 + 8 + 4 * c + 4 * c + (k.rows.row(r).tinted.empty() ? 0 : 12 * c);
    }
    return at;
  }
  size_t rowTarget(int i, size_t k) const { return row(i) + 13 + 4 * k; }
  size_t rowValue(int i, size_t k) const {
    return row(i) + 13 + 4 * sample().rows.row(i).targets.size() + 4 * k;
  }
};

Layout layoutOf(const std::string& bytes) {
  Layout l;
  uint64_t h = 0;
  std::memcpy(&h, bytes.data() + kMagicBytes, 8);
  l.headerBytes = h;
  l.header = kMagicBytes + 8;
  l.area = l.header + h;
  l.irradiance = l.area + 8 * 4;
  l.rows = l.irradiance + 2 * 3 * 8 * 4;
  return l;
}

template <typename T>
std::string patched(std::string bytes, size_t offset, T value) {
  EXPECT_LE(offset + sizeof(T), bytes.size());
  std::memcpy(bytes.data() + offset, &value, sizeof(T));
  return bytes;
}

// The file with its header replaced by `edit` applied to the header's JSON (length rewritten).
std::string withHeader(const std::string& bytes, const std::function<void(nlohmann::json&)>& edit) {
  const Layout l = layoutOf(bytes);
  nlohmann::json header = nlohmann::json::parse(bytes.substr(l.header, l.headerBytes));
  edit(header);
  const std::string text = header.dump();
  std::string out = bytes.substr(0, kMagicBytes);
  const uint64_t n = text.size();
  out.append(reinterpret_cast<const char*>(&n), 8);
  out += text;
  out += bytes.substr(l.area);
  return out;
}

class KeptFactorsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        fs::temp_directory_path() / ("radiosity_kept_factors_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    path_ = (dir_ / "factors.bin").string();
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  void write(const std::string& bytes) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good());
  }

  // The file holding `bytes` must be refused with an InputError naming it (and saying `what`,
  // when given); any other outcome fails the test.
  void expectRejected(const std::string& bytes, const std::string& what = "") const {
    write(bytes);
    try {
      readKeptFactors(path_);
      ADD_FAILURE() << "accepted a bad file (" << bytes.size() << " bytes)";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path_) << e.what();
      if (!what.empty()) {
        EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what();
    }
  }

  fs::path dir_;
  std::string path_;
};

TEST_F(KeptFactorsTest, RoundTripKeepsEveryField) {
  const KeptFactors in = sample();
  write(bytesOf(in));
  const KeptFactors out = readKeptFactors(path_);

  EXPECT_EQ(out.scenePath, in.scenePath);
  EXPECT_EQ(out.fingerprint, in.fingerprint);
  EXPECT_EQ(out.options.scenePath, in.scenePath);
  EXPECT_EQ(out.options.raysPerElement, 64);
  EXPECT_EQ(out.options.seed, 7u);
  EXPECT_EQ(out.options.targetElements, 4);
  EXPECT_EQ(out.options.solver, SolverKind::GaussSeidel);
  EXPECT_EQ(out.options.tolerance, 1e-5);
  EXPECT_EQ(out.options.maxIterations, 50);
  EXPECT_EQ(out.options.twoSided.all, false);
  EXPECT_EQ(out.options.twoSided.materials, in.options.twoSided.materials);
  EXPECT_TRUE(out.options.keepFactors);
  EXPECT_EQ(out.area, in.area);
  EXPECT_EQ(out.lightGroups, in.lightGroups);
  EXPECT_EQ(out.lightTypes, in.lightTypes);
  ASSERT_EQ(out.lightIrradiance.size(), 2u);
  for (size_t l = 0; l < 2; ++l) {
    ASSERT_EQ(out.lightIrradiance[l].size(), 4u);
    for (size_t i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(out.lightIrradiance[l][i][c], in.lightIrradiance[l][i][c]) << l << " " << i;
  }
  ASSERT_EQ(out.rows.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const FormFactorRow a = sampleRows()[i];
    const FormFactorRow b = out.rows.row(i);
    EXPECT_EQ(b.targets, a.targets) << "row " << i;
    EXPECT_EQ(b.escaped, a.escaped) << "row " << i;
    ASSERT_EQ(b.values.size(), a.values.size()) << "row " << i;
    for (size_t k = 0; k < a.values.size(); ++k)
      EXPECT_EQ(b.values[k], static_cast<double>(static_cast<float>(a.values[k])));
    ASSERT_EQ(b.tinted.size(), a.tinted.size()) << "row " << i;
    for (size_t k = 0; k < a.tinted.size(); ++k)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(b.tinted[k][c], static_cast<double>(static_cast<float>(a.tinted[k][c])));
    EXPECT_TRUE(b.points.empty());
  }
  // 0.1 is no float: the rounding is real, so the comparison above is not a tautology.
  EXPECT_NE(out.rows.row(3).values[0], 0.1);
  // The mesh and inputs update compares against.
  EXPECT_EQ(out.elementEdge, in.elementEdge);
  EXPECT_EQ(out.corners, in.corners);
  EXPECT_EQ(out.material, in.material);
  EXPECT_EQ(out.patch, in.patch);
  EXPECT_EQ(out.rayMultiplier, in.rayMultiplier);
  EXPECT_EQ(out.lightInput.file, in.lightInput.file);
  EXPECT_EQ(out.lightsFingerprint, in.lightsFingerprint);
  EXPECT_EQ(out.materialVisibility, in.materialVisibility);
  ASSERT_EQ(out.lightInput.shortcuts.size(), 2u);
  EXPECT_EQ(out.lightInput.shortcuts[0].type, LightType::Sky);
  EXPECT_EQ(out.lightInput.shortcuts[0].radiance.g, 0.4);
  EXPECT_EQ(out.lightInput.shortcuts[1].type, LightType::Directional);
  EXPECT_EQ(out.lightInput.shortcuts[1].irradiance.b, 6);
  // Bit for bit (a saved solution's fingerprint holds it): not normalised a second time.
  EXPECT_EQ(out.lightInput.shortcuts[1].direction, in.lightInput.shortcuts[1].direction);

  // Written again, the file is the same bytes.
  EXPECT_EQ(bytesOf(out), bytesOf(in));
}

TEST_F(KeptFactorsTest, NoElementsNoLightsRoundTrip) {
  KeptFactors in = sample();
  in.area.clear();
  in.rows = KeptRowTable();
  in.lightGroups.clear();
  in.lightTypes.clear();
  in.lightIrradiance.clear();
  in.corners.clear();
  in.material.clear();
  in.patch.clear();
  in.rayMultiplier.clear();
  write(bytesOf(in));
  const KeptFactors out = readKeptFactors(path_);
  EXPECT_TRUE(out.area.empty());
  EXPECT_EQ(out.rows.size(), 0u);
  EXPECT_TRUE(out.lightIrradiance.empty());
  EXPECT_EQ(out.fingerprint, "abc");
}

TEST_F(KeptFactorsTest, EveryTruncationIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  ASSERT_LT(bytes.size(), 3000u);  // small enough to try every length
  for (size_t length = 0; length < bytes.size(); ++length) {
    SCOPED_TRACE("length " + std::to_string(length));
    expectRejected(bytes.substr(0, length));
  }
}

TEST_F(KeptFactorsTest, BytesAfterTheMeshAreAnInputError) {
  const std::string bytes = bytesOf(sample());
  expectRejected(bytes + '\0', "after the mesh");
  expectRejected(bytes + std::string(100, 'x'), "after the mesh");
}

TEST_F(KeptFactorsTest, BadMeshIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const size_t n = 4, mesh = layoutOf(bytes).row(4);
  expectRejected(patched<double>(bytes, mesh + 8 * 4, std::nan("")), "corners are not finite");
  expectRejected(patched<int32_t>(bytes, mesh + 72 * n + 4, -1), "negative material");
  expectRejected(patched<int32_t>(bytes, mesh + 76 * n + 8, -3), "negative material or patch");
  expectRejected(patched<uint8_t>(bytes, mesh + 80 * n + 2, 0), "ray multiplier");
  expectRejected(patched<uint8_t>(bytes, mesh + 80 * n + 3, 65), "ray multiplier");
  // The same places with the values already there read (the offsets above are the layout's).
  std::string same = patched<double>(bytes, mesh + 8 * 4, 1.0);
  same = patched<int32_t>(same, mesh + 72 * n + 4, 1);
  same = patched<int32_t>(same, mesh + 76 * n + 8, 1);
  same = patched<uint8_t>(same, mesh + 80 * n + 2, 43);
  EXPECT_EQ(same, bytes);
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["element_edge"] = 0; }),
                 "element_edge");
  expectRejected(withHeader(bytes,
                            [](nlohmann::json& h) {
                              h["material_visibility"] = {1, 2};
                            }),
                 "the header is not the expected JSON");
  expectRejected(
      withHeader(bytes, [](nlohmann::json& h) { h["material_visibility"]["white"] = 5; }),
      "the header is not the expected JSON");
  expectRejected(withHeader(bytes,
                            [](nlohmann::json& h) {
                              h["light_input"]["shortcuts"][0] = {{"sky", {1, 2}}};
                            }),
                 "sky shortcut");
  expectRejected(withHeader(bytes,
                            [](nlohmann::json& h) {
                              h["light_input"]["shortcuts"][1] = {{"sun", {0, 0, 0, 1, 1, 1}}};
                            }),
                 "shortcuts are not valid");
}

TEST_F(KeptFactorsTest, AnOlderFormatSaysToSolveAgain) {
  const std::string bytes = bytesOf(sample());
  expectRejected(patched<char>(bytes, 23, '1'), "older version");
}

TEST_F(KeptFactorsTest, MissingFileIsAnInputError) {
  expectRejected("x");  // the fixture's file exists; now a path that does not
  try {
    readKeptFactors((dir_ / "missing.bin").string());
    ADD_FAILURE() << "read a missing file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir_ / "missing.bin").string());
  }
}

TEST_F(KeptFactorsTest, WrongMagicIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  expectRejected(patched<char>(bytes, 0, 'R'), "not a kept form factors file");
  expectRejected(patched<char>(bytes, 23, '3'), "not a kept form factors file");
}

TEST_F(KeptFactorsTest, HeaderLengthPastTheEndIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const uint64_t past = bytes.size() - kMagicBytes - 8 + 1;
  expectRejected(patched<uint64_t>(bytes, kMagicBytes, past), "past the file's end");
  expectRejected(patched<uint64_t>(bytes, kMagicBytes, std::numeric_limits<uint64_t>::max()),
                 "past the file's end");
  // Shorter than the JSON: the header is cut mid-object.
  expectRejected(patched<uint64_t>(bytes, kMagicBytes, layoutOf(bytes).headerBytes - 1));
}

TEST_F(KeptFactorsTest, HeaderThatIsNotJsonIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  expectRejected(patched<char>(bytes, l.header, 'x'), "not the expected JSON");
  expectRejected(patched<char>(bytes, l.header + l.headerBytes - 1, ','), "not the expected JSON");
  expectRejected(withHeader(bytes,
                            [](nlohmann::json& h) {
                              h = nlohmann::json::array({1, 2});
                            }),
                 "not the expected JSON");
}

TEST_F(KeptFactorsTest, HeaderWithoutOptionsIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  // The same length, "options" renamed: the areas and rows stay where they were.
  const size_t at = bytes.find("\"options\"", l.header);
  ASSERT_LT(at, l.area);
  std::string renamed = bytes;
  renamed[at + 7] = 'z';
  expectRejected(renamed, "not the expected JSON");
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h.erase("options"); }),
                 "not the expected JSON");
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"].erase("rays"); }),
                 "options are incomplete");
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["lights"][1].erase("group"); }),
                 "not the expected JSON");
}

TEST_F(KeptFactorsTest, InvalidHeaderOptionsAreAnInputError) {
  const std::string bytes = bytesOf(sample());
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"]["rays"] = 0; }),
                 "not valid");
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"]["tolerance"] = -1; }),
                 "not valid");
  // An unknown solver: parseSolverKind's error, naming this file.
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"]["solver"] = "magic"; }),
                 "magic");
  // Integers that are not: fractions, and numbers past the field's range (a float cast to int
  // past its range would be undefined behaviour).
  for (const char* key : {"rays", "elements", "max_iterations", "seed"}) {
    SCOPED_TRACE(key);
    expectRejected(withHeader(bytes, [&](nlohmann::json& h) { h["options"][key] = 64.5; }));
    expectRejected(withHeader(bytes, [&](nlohmann::json& h) { h["options"][key] = 1e300; }));
    expectRejected(withHeader(bytes, [&](nlohmann::json& h) { h["options"][key] = -1e300; }));
  }
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"]["rays"] = 1ull << 40; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["options"]["seed"] = -1; }));
}

TEST_F(KeptFactorsTest, BadElementCountIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  // More elements than the arrays hold, fewer (then the rest is left over), none, and past any
  // solve: never an allocation of the header's size.
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 5; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 3; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 0; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 1ull << 62; }),
                 "more than a solve makes");
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 3999999; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = -1; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 4.5; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = 1e300; }));
  expectRejected(withHeader(bytes, [](nlohmann::json& h) { h["elements"] = "4"; }));
}

TEST_F(KeptFactorsTest, TargetOutOfRangeIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  expectRejected(patched<int32_t>(bytes, l.rowTarget(0, 2), 4), "targets must be increasing");
  expectRejected(patched<int32_t>(bytes, l.rowTarget(0, 0), -1), "targets must be increasing");
  expectRejected(patched<int32_t>(bytes, l.rowTarget(3, 2), std::numeric_limits<int32_t>::max()),
                 "targets must be increasing");
}

TEST_F(KeptFactorsTest, TargetsNotIncreasingAreAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  expectRejected(patched<int32_t>(bytes, l.rowTarget(0, 1), 1), "targets must be increasing");
  expectRejected(patched<int32_t>(bytes, l.rowTarget(1, 1), 0), "targets must be increasing");
}

TEST_F(KeptFactorsTest, BadFactorsAreAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  expectRejected(patched<float>(bytes, l.rowValue(0, 0), -0.25f), "factors finite, >= 0");
  expectRejected(patched<float>(bytes, l.rowValue(3, 1), std::nanf("")), "factors finite, >= 0");
  expectRejected(patched<float>(bytes, l.rowValue(1, 0), HUGE_VALF), "factors finite, >= 0");
  expectRejected(patched<float>(bytes, l.rowValue(0, 2), 0.9f), "sum past 1");
  // The tinted factors of row 1 follow its values.
  const size_t tinted = l.rowValue(1, 2);
  expectRejected(patched<float>(bytes, tinted + 4, -0.1f), "tinted factors");
  expectRejected(patched<float>(bytes, tinted + 20, std::nanf("")), "tinted factors");
  // The row's head: escaped not finite or negative, a tinted flag past 1, more targets than
  // elements.
  expectRejected(patched<double>(bytes, l.row(0) + 5, std::nan("")), "not a form-factor row");
  expectRejected(patched<double>(bytes, l.row(0) + 5, -0.5), "not a form-factor row");
  expectRejected(patched<uint8_t>(bytes, l.row(0) + 4, 2), "not a form-factor row");
  expectRejected(patched<uint32_t>(bytes, l.row(2), 5), "not a form-factor row");
  expectRejected(patched<uint32_t>(bytes, l.row(2), 0xffffffffu), "not a form-factor row");
}

TEST_F(KeptFactorsTest, BadAreaIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  expectRejected(patched<double>(bytes, l.area + 8, std::nan("")), "area");
  expectRejected(patched<double>(bytes, l.area + 24, -1.0), "area");
  expectRejected(patched<double>(bytes, l.area, HUGE_VAL), "area");
}

TEST_F(KeptFactorsTest, BadIrradianceIsAnInputError) {
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  // Light 1, element 2, green.
  expectRejected(patched<double>(bytes, l.irradiance + 8 * (12 + 3 * 2 + 1), -1.0),
                 "light 1's irradiance");
  expectRejected(patched<double>(bytes, l.irradiance, std::nan("")), "light 0's irradiance");
}

TEST_F(KeptFactorsTest, PatchedSampleStillReads) {
  // The offsets the tests above patch are where the layout says: the same patches with the
  // values already there leave a file that reads.
  const std::string bytes = bytesOf(sample());
  const Layout l = layoutOf(bytes);
  std::string same = patched<int32_t>(bytes, l.rowTarget(0, 2), 3);
  same = patched<float>(same, l.rowValue(0, 0), 0.25f);
  same = patched<double>(same, l.area + 8, 0.25);
  same = patched<double>(same, l.irradiance + 8 * (12 + 3 * 2 + 1), 2.0);
  same = patched<uint32_t>(same, l.row(2), 0);
  same = patched<double>(same, l.row(0) + 5, 0.325);
  ASSERT_EQ(same, bytes);
  // After the rows, the mesh: 9 corners' f64, a material and a patch i32, a multiplier u8 each.
  EXPECT_EQ(l.row(4) + 4 * (72 + 4 + 4 + 1), bytes.size());
  write(withHeader(bytes, [](nlohmann::json& h) { h["scene"] = "elsewhere/scene.obj"; }));
  EXPECT_EQ(readKeptFactors(path_).scenePath, "elsewhere/scene.obj");
}

}  // namespace
}  // namespace rad
