#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "meshing/vertex_interpolation.h"
#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/output/display_radiance.h"
#include "radiosity/output/elements_csv.h"
#include "radiosity/output/tone_map.h"
#include "radiosity/output/vertex_colors_ply.h"

namespace rad {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit square in z = 0, facing +z, as one quad polygon (two triangular elements).
PatchMesh unitSquare() {
  return PatchMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{{0, 1, 2, 3}, 0}});
}

// Two unit squares sharing the edge x = 1 in the plane z = 0, both facing +z.
PatchMesh coplanarPair(int materialA, int materialB) {
  return PatchMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                   {{{0, 1, 2, 3}, materialA}, {{1, 4, 5, 2}, materialB}});
}

// An L: the floor z = 0 (facing +z) and the wall x = 0 (facing +x), sharing the edge along y.
PatchMesh foldedPair(int materialFloor, int materialWall) {
  return PatchMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}},
                   {{{0, 1, 2, 3}, materialFloor}, {{0, 3, 4, 5}, materialWall}});
}

// ---------------------------------------------------------------------------------------------
// A small reader for binary little-endian PLY, independent of the writer: it follows the header
// it finds rather than assuming the writer's layout.

struct PlyProperty {
  std::string name, type;
  bool list = false;
  std::string countType;
};
struct PlyElement {
  std::string name;
  int count = 0;
  std::vector<PlyProperty> properties;
  std::vector<std::map<std::string, double>> scalars;  // per item: property → value
  std::vector<std::map<std::string, std::vector<long>>> lists;
};
struct PlyFile {
  std::string format;
  std::vector<std::string> comments;
  std::vector<PlyElement> elements;
  const PlyElement& element(const std::string& name) const {
    for (const auto& e : elements)
      if (e.name == name) return e;
    throw std::runtime_error("no element " + name);
  }
};

int typeSize(const std::string& t) {
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if (t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32")
    return 4;
  if (t == "double" || t == "float64") return 8;
  throw std::runtime_error("unknown PLY type " + t);
}

double readValue(const std::string& data, size_t& at, const std::string& t) {
  const int size = typeSize(t);
  if (at + size > data.size()) throw std::runtime_error("PLY body truncated");
  std::uint64_t bits = 0;
  for (int k = 0; k < size; ++k)
    bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(data[at + k])) << (8 * k);
  at += size;
  if (t == "float" || t == "float32") {
    const auto u = static_cast<std::uint32_t>(bits);
    float f;
    std::memcpy(&f, &u, 4);
    return f;
  }
  if (t == "double" || t == "float64") {
    double d;
    std::memcpy(&d, &bits, 8);
    return d;
  }
  if (t == "int" || t == "int32") return static_cast<std::int32_t>(bits);
  if (t == "short" || t == "int16") return static_cast<std::int16_t>(bits);
  if (t == "char" || t == "int8") return static_cast<std::int8_t>(bits);
  return static_cast<double>(bits);
}

PlyFile parsePly(const std::string& data) {
  PlyFile ply;
  const std::string endHeader = "end_header\n";
  const size_t headerEnd = data.find(endHeader);
  if (data.compare(0, 4, "ply\n") != 0 || headerEnd == std::string::npos)
    throw std::runtime_error("not a PLY file");
  std::istringstream header(data.substr(0, headerEnd));
  std::string line;
  std::getline(header, line);  // "ply"
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string version;
      words >> ply.format >> version;
      if (version != "1.0") throw std::runtime_error("PLY version " + version);
    } else if (keyword == "comment") {
      ply.comments.push_back(line.substr(8));
    } else if (keyword == "element") {
      PlyElement e;
      words >> e.name >> e.count;
      ply.elements.push_back(e);
    } else if (keyword == "property") {
      PlyProperty p;
      words >> p.type;
      if (p.type == "list") {
        p.list = true;
        words >> p.countType >> p.type;
      }
      words >> p.name;
      ply.elements.back().properties.push_back(p);
    } else {
      throw std::runtime_error("unexpected header line: " + line);
    }
  }
  if (ply.format != "binary_little_endian") throw std::runtime_error("format " + ply.format);
  size_t at = headerEnd + endHeader.size();
  for (auto& e : ply.elements) {
    e.scalars.resize(e.count);
    e.lists.resize(e.count);
    for (int i = 0; i < e.count; ++i)
      for (const auto& p : e.properties) {
        if (!p.list) {
          e.scalars[i][p.name] = readValue(data, at, p.type);
          continue;
        }
        const auto n = static_cast<long>(readValue(data, at, p.countType));
        for (long k = 0; k < n; ++k)
          e.lists[i][p.name].push_back(static_cast<long>(readValue(data, at, p.type)));
      }
  }
  if (at != data.size()) throw std::runtime_error("trailing bytes after the PLY body");
  return ply;
}

std::string writePly(const PatchMesh& mesh, const VertexInterpolation& vi,
                     const std::vector<Rgb>& radiosity, const ToneMap& toneMap) {
  std::ostringstream out(std::ios::binary);
  writeVertexColorsPly(out, vi, mesh, interpolateVertexRadiance(vi, radiosity), toneMap);
  return out.str();
}

// ---------------------------------------------------------------------------------------------
// A small CSV reader.

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

double relativeError(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

// ---------------------------------------------------------------------------------------------
// sRGB and the tone map.

TEST(SrgbEncode, KnownValues) {
  EXPECT_EQ(srgbEncode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgbEncode(1.0), 1.0);
  EXPECT_NEAR(srgbEncode(0.5), 0.735357, 1e-6);
  EXPECT_NEAR(srgbEncode(0.001), 0.01292, 1e-15);  // linear segment
  EXPECT_NEAR(srgbEncode(0.18), 0.461356, 1e-6);   // photographic mid-grey
  // Clamped outside [0, 1].
  EXPECT_EQ(srgbEncode(-0.5), 0.0);
  EXPECT_EQ(srgbEncode(7.0), 1.0);
  EXPECT_EQ(srgbEncode(std::nan("")), 0.0);
}

TEST(SrgbEncode, ContinuousAndMonotonicAtTheLinearSegment) {
  const double t = 0.0031308;
  // The two pieces of IEC 61966-2-1 meet to within 3e-8 at the threshold.
  EXPECT_NEAR(srgbEncode(t), 12.92 * t, 1e-12);
  EXPECT_NEAR(srgbEncode(std::nextafter(t, 1.0)), 12.92 * t, 1e-7);
  double previous = -1;
  for (int i = 0; i <= 1000; ++i) {
    const double x = 2 * t * i / 1000.0;
    const double y = srgbEncode(x);
    EXPECT_GE(y, previous) << x;
    previous = y;
  }
}

TEST(ToneMap, AutoExposureMapsAUniformFieldToOne) {
  const Rgb c(0.3, 0.6, 0.9);
  const double luminance = 0.2126 * 0.3 + 0.7152 * 0.6 + 0.0722 * 0.9;  // 0.55788
  const ToneMap tm = ToneMap::autoExposure(std::vector<Rgb>(50, c), std::vector<double>(50, 0.7));
  EXPECT_NEAR(tm.exposure, 1.0 / 0.55788, 1e-12);
  EXPECT_NEAR(tm.exposure * luminance, 1.0, 1e-12);
}

// The display exposure is set by the lit surfaces: an emitter covering half the area at 100× the
// radiance of the rest would otherwise take the 99th percentile and leave the scene at 1/100.
TEST(ToneMap, SolutionExposureIgnoresEmitters) {
  const std::vector<Rgb> radiosity = {Rgb::all(100 * M_PI), Rgb::all(M_PI)};  // L = 100, 1
  const std::vector<double> area = {0.5, 0.5};
  EXPECT_NEAR(solutionToneMap(radiosity, area, {Rgb::all(1), Rgb()}).exposure, 1.0, 1e-12);
  EXPECT_NEAR(solutionToneMap(radiosity, area, {Rgb(), Rgb()}).exposure, 0.01, 1e-12);
  // Every element emits: nothing lit is left, so all of them count.
  EXPECT_NEAR(solutionToneMap(radiosity, area, {Rgb::all(1), Rgb::all(1)}).exposure, 0.01, 1e-12);
}

TEST(ToneMap, AutoExposurePercentileIsWeighted) {
  const std::vector<Rgb> values = {Rgb::all(1.0), Rgb::all(100.0)};  // luminance 1 and 100
  // 99.5% of the area at luminance 1: the 99th percentile is 1.
  EXPECT_NEAR(ToneMap::autoExposure(values, {0.995, 0.005}).exposure, 1.0, 1e-12);
  // 99.5% at luminance 100: the 99th percentile is 100.
  EXPECT_NEAR(ToneMap::autoExposure(values, {0.005, 0.995}).exposure, 0.01, 1e-14);
}

TEST(ToneMap, AutoExposureRanksValues) {
  // Luminances 1..100 in shuffled order, equal weights: the 99th percentile is 99.
  std::vector<Rgb> values;
  for (int i = 0; i < 100; ++i) values.push_back(Rgb::all(1 + (i * 37) % 100));
  EXPECT_NEAR(ToneMap::autoExposure(values, {}).exposure, 1.0 / 99.0, 1e-15);
  EXPECT_NEAR(ToneMap::autoExposure(values, std::vector<double>(100, 2.5)).exposure, 1.0 / 99.0,
              1e-15);
}

TEST(ToneMap, AutoExposureIgnoresBlack) {
  std::vector<Rgb> values(1000, Rgb());
  values.push_back(Rgb::all(4.0));
  EXPECT_NEAR(ToneMap::autoExposure(values, std::vector<double>(1001, 1.0)).exposure, 0.25, 1e-15);
  EXPECT_EQ(ToneMap::autoExposure(std::vector<Rgb>(10, Rgb()), {}).exposure, 1.0);
  EXPECT_EQ(ToneMap::autoExposure({}, {}).exposure, 1.0);
}

TEST(ToneMap, AutoExposureRejectsBadWeights) {
  EXPECT_THROW(ToneMap::autoExposure({Rgb::all(1)}, {1.0, 2.0}), CheckFailure);
  EXPECT_THROW(ToneMap::autoExposure({Rgb::all(1)}, {-1.0}), CheckFailure);
}

TEST(ToneMap, ToSrgb8KnownValues) {
  // round(255 * srgb(x)): srgb(0.5) = 0.735357 → 187.52 → 188; srgb(0.25) = 0.537099 → 136.96
  // → 137; srgb(0.1) = 0.349190 → 89.04 → 89.
  using C = std::array<std::uint8_t, 3>;
  EXPECT_EQ(ToneMap{1.0}.toSrgb8(Rgb(0.5, 0.25, 1.0)), (C{188, 137, 255}));
  EXPECT_EQ(ToneMap{2.0}.toSrgb8(Rgb(0.25, 0.125, 0.05)), (C{188, 137, 89}));
  EXPECT_EQ(ToneMap{1.0}.toSrgb8(Rgb(-1.0, 0.0, 3.0)), (C{0, 0, 255}));
}

// ---------------------------------------------------------------------------------------------
// Elements CSV.

TEST(ElementsCsv, HeaderRowsAndRoundTrip) {
  const PatchMesh mesh = unitSquare();
  ASSERT_EQ(mesh.elementCount(), 2);
  // Values with no short decimal form, so too few digits would show.
  const std::vector<Rgb> b = {Rgb(1.0 / 3.0, 2.0 / 7.0, 0.1 * kPi),
                              Rgb(1e-300, 12345.678901234567, 0)};
  std::ostringstream out;
  out.precision(3);  // the writer must not depend on (or keep) the caller's precision
  writeElementsCsv(out, mesh, b);
  EXPECT_EQ(out.precision(), 3);

  const auto rows = parseCsv(out.str());
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> header = {"element", "patch", "material", "area", "cx",  "cy",
                                           "cz",      "nx",    "ny",       "nz",   "B_r", "B_g",
                                           "B_b",     "L_r",   "L_g",      "L_b"};
  EXPECT_EQ(rows[0], header);

  double areaSum = 0;
  Eigen::Vector3d weightedCentroid = Eigen::Vector3d::Zero();
  for (int e = 0; e < 2; ++e) {
    const auto& row = rows[e + 1];
    ASSERT_EQ(row.size(), 16u);
    std::vector<double> v;
    for (const auto& cell : row) v.push_back(std::stod(cell));
    EXPECT_EQ(std::stoi(row[0]), e);
    EXPECT_EQ(std::stoi(row[1]), 0);
    EXPECT_EQ(std::stoi(row[2]), 0);
    EXPECT_NEAR(v[3], 0.5, 1e-15);  // half the unit square
    areaSum += v[3];
    weightedCentroid += v[3] * Eigen::Vector3d(v[4], v[5], v[6]);
    // The centroid is the mean of the element's corners.
    const auto corners = mesh.corners(e);
    const Eigen::Vector3d mean = (corners[0] + corners[1] + corners[2]) / 3.0;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v[4 + k], mean[k], 1e-15);
    EXPECT_NEAR(v[7], 0.0, 1e-15);
    EXPECT_NEAR(v[8], 0.0, 1e-15);
    EXPECT_NEAR(v[9], 1.0, 1e-15);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LE(relativeError(v[10 + c], b[e][c]), 1e-15) << row[10 + c];
      EXPECT_LE(relativeError(v[13 + c], b[e][c] / kPi), 1e-15) << row[13 + c];
    }
  }
  EXPECT_NEAR(areaSum, 1.0, 1e-15);
  EXPECT_NEAR(weightedCentroid.x(), 0.5, 1e-15);
  EXPECT_NEAR(weightedCentroid.y(), 0.5, 1e-15);
  EXPECT_NEAR(weightedCentroid.z(), 0.0, 1e-15);
}

TEST(ElementsCsv, MaterialsPatchesAndNormalsOfAnL) {
  const PatchMesh mesh = foldedPair(3, 5);
  ASSERT_EQ(mesh.elementCount(), 4);
  std::ostringstream out;
  writeElementsCsv(out, mesh, std::vector<Rgb>(4, Rgb::all(kPi)));
  const auto rows = parseCsv(out.str());
  ASSERT_EQ(rows.size(), 5u);
  int floor = 0, wall = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    const int patch = std::stoi(rows[i][1]);
    const int material = std::stoi(rows[i][2]);
    const Eigen::Vector3d n(std::stod(rows[i][7]), std::stod(rows[i][8]), std::stod(rows[i][9]));
    const Eigen::Vector3d c(std::stod(rows[i][4]), std::stod(rows[i][5]), std::stod(rows[i][6]));
    if (patch == 0) {
      ++floor;
      EXPECT_EQ(material, 3);
      EXPECT_NEAR((n - Eigen::Vector3d(0, 0, 1)).norm(), 0, 1e-15);
      EXPECT_NEAR(c.z(), 0, 1e-15);
    } else {
      ++wall;
      EXPECT_EQ(patch, 1);
      EXPECT_EQ(material, 5);
      EXPECT_NEAR((n - Eigen::Vector3d(1, 0, 0)).norm(), 0, 1e-15);
      EXPECT_NEAR(c.x(), 0, 1e-15);
    }
    for (int k = 13; k < 16; ++k) EXPECT_NEAR(std::stod(rows[i][k]), 1.0, 1e-15);  // π/π
  }
  EXPECT_EQ(floor, 2);
  EXPECT_EQ(wall, 2);
}

TEST(ElementsCsv, RejectsAWrongNumberOfValues) {
  std::ostringstream out;
  EXPECT_THROW(writeElementsCsv(out, unitSquare(), std::vector<Rgb>(3)), CheckFailure);
}

// The reader beside the writer: what was written reads back bit-exact, row by row.
TEST(ElementsCsvReader, RoundTripIsBitExact) {
  const PatchMesh mesh = foldedPair(3, 5);
  const std::vector<Rgb> b = {Rgb(1.0 / 3.0, 2.0 / 7.0, 0.1 * kPi),
                              Rgb(1e-300, 12345.678901234567, 0), Rgb(0, 0, 0), Rgb(7, 8, 9)};
  const auto path = std::filesystem::temp_directory_path() / "radiosity_elements_roundtrip.csv";
  {
    std::ofstream out(path);
    writeElementsCsv(out, mesh, b);
  }
  const ElementsCsv csv = readElementsCsv(path.string());
  EXPECT_FALSE(csv.hasBuriedCells);
  EXPECT_FALSE(csv.hasDirectIrradiance);
  const std::vector<ElementsCsvRow>& rows = csv.rows;
  ASSERT_EQ(rows.size(), 4u);
  for (int e = 0; e < 4; ++e) {
    const ElementsCsvRow& row = rows[e];
    EXPECT_EQ(row.line, e + 2);
    EXPECT_EQ(row.element, e);
    EXPECT_EQ(row.patch, mesh.patch(e));
    EXPECT_EQ(row.material, mesh.material(e));
    EXPECT_EQ(row.area, mesh.area(e));
    EXPECT_EQ(row.centroid, mesh.centroid(e));
    EXPECT_EQ(row.normal, mesh.normal(e));
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(row.radiosity[c], b[e][c]);
      EXPECT_EQ(row.radiance[c], b[e][c] / M_PI);
    }
  }
  std::filesystem::remove(path);
}

// The buried cells column: every mask of 64 bits reads back as written, and the column is
// there only when the writer is given the masks.
TEST(ElementsCsvReader, BuriedCellsReadBackAsWritten) {
  const PatchMesh mesh = foldedPair(3, 5);
  const std::vector<uint64_t> buried = {0, ~uint64_t{0}, uint64_t{1} << 63, 0x00ff00f0000a0001};
  std::stringstream file;
  writeElementsCsv(file, mesh, std::vector<Rgb>(4, Rgb::all(1)), &buried);
  const std::string text = file.str();
  EXPECT_EQ(text.substr(0, text.find('\n')), std::string(kElementsCsvHeader) + ",buried_cells");
  const ElementsCsv csv = readElementsCsv(file, "sol.csv");
  EXPECT_TRUE(csv.hasBuriedCells);
  ASSERT_EQ(csv.rows.size(), 4u);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(csv.rows[e].buriedCells, buried[e]) << e;
  EXPECT_NE(text.find(",ffffffffffffffff\n"), std::string::npos);  // hexadecimal, 16 digits
  const std::vector<uint64_t> tooFew(3);
  EXPECT_THROW(writeElementsCsv(file, mesh, std::vector<Rgb>(4), &tooFew), CheckFailure);
}

// The direct irradiance columns (Ed_r,Ed_g,Ed_b, after L_b and before buried_cells): every value
// reads back bit-exact, with and without the buried cells after them.
TEST(ElementsCsvReader, DirectIrradianceReadsBackBitExact) {
  const PatchMesh mesh = foldedPair(3, 5);
  const std::vector<Rgb> b = {Rgb(1, 2, 3), Rgb(4, 5, 6), Rgb(7, 8, 9), Rgb(0.5, 0.25, 0.125)};
  // Values with no short decimal form, a subnormal, a huge value and zeros (black elements).
  const std::vector<Rgb> direct = {Rgb(1.0 / 3.0, 2.0 / 7.0, 0.1 * kPi),
                                   Rgb(1e-300, 12345.678901234567, 0), Rgb(0, 0, 0),
                                   Rgb(4.9406564584124654e-324, 1.7976931348623157e308, 0.1)};
  const std::vector<uint64_t> buried = {0, ~uint64_t{0}, uint64_t{1} << 63, 0x00ff00f0000a0001};
  for (const bool withBuried : {false, true}) {
    SCOPED_TRACE(withBuried ? "with buried_cells" : "without buried_cells");
    std::stringstream file;
    writeElementsCsv(file, mesh, b, withBuried ? &buried : nullptr, &direct);
    const std::string text = file.str();
    EXPECT_EQ(text.substr(0, text.find('\n')), std::string(kElementsCsvHeader) + ",Ed_r,Ed_g,Ed_b" +
                                                   (withBuried ? ",buried_cells" : ""));
    // Row 0's Ed values follow its L_b, in the shortest round-trip text.
    const std::string row0 = text.substr(text.find('\n') + 1);
    std::vector<std::string> f;
    std::istringstream fields(row0.substr(0, row0.find('\n')));
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    ASSERT_EQ(f.size(), withBuried ? 20u : 19u);
    EXPECT_EQ(f[16], "0.3333333333333333");
    EXPECT_EQ(f[17], "0.2857142857142857");
    const ElementsCsv csv = readElementsCsv(file, "sol.csv");
    EXPECT_TRUE(csv.hasDirectIrradiance);
    EXPECT_EQ(csv.hasBuriedCells, withBuried);
    ASSERT_EQ(csv.rows.size(), 4u);
    for (int e = 0; e < 4; ++e) {
      const ElementsCsvRow& row = csv.rows[e];
      EXPECT_EQ(row.element, e);
      EXPECT_EQ(row.centroid, mesh.centroid(e));
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(row.directIrradiance[c], direct[e][c]) << e << " " << c;
        EXPECT_EQ(row.radiosity[c], b[e][c]) << e << " " << c;
        EXPECT_EQ(row.radiance[c], b[e][c] / M_PI) << e << " " << c;
      }
      EXPECT_EQ(row.buriedCells, withBuried ? buried[e] : 0u) << e;
    }
  }
  // One value per element, or the writer refuses.
  std::ostringstream out;
  const std::vector<Rgb> tooFew(3);
  EXPECT_THROW(writeElementsCsv(out, mesh, b, nullptr, &tooFew), CheckFailure);
  EXPECT_THROW(writeElementsCsv(out, mesh, b, &buried, &tooFew), CheckFailure);
}

// A file written before the Ed columns were kept (with or without buried_cells) reads as before:
// no direct irradiance, every row's 0.
TEST(ElementsCsvReader, AnOlderFileWithoutTheEdColumnsStillReads) {
  const std::string row0 =
      "0,0,3,0.5,0.6666666666666666,0,0.3333333333333333,0,1,0,1.5,2.5,3.5,"
      "0.477464829275686,0.7957747154594768,1.1140846016432675";
  for (const bool withBuried : {false, true}) {
    std::istringstream in(std::string(kElementsCsvHeader) + (withBuried ? ",buried_cells" : "") +
                          "\n" + row0 + (withBuried ? ",f0" : "") + "\n");
    const ElementsCsv csv = readElementsCsv(in, "old.csv");
    EXPECT_FALSE(csv.hasDirectIrradiance);
    EXPECT_EQ(csv.hasBuriedCells, withBuried);
    ASSERT_EQ(csv.rows.size(), 1u);
    EXPECT_EQ(csv.rows[0].material, 3);
    EXPECT_EQ(csv.rows[0].radiosity.g, 2.5);
    EXPECT_EQ(csv.rows[0].buriedCells, withBuried ? 0xf0u : 0u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(csv.rows[0].directIrradiance[c], 0.0);
  }
}

// Bad Ed values and rows that do not fit the Ed header: an InputError naming the file and line.
TEST(ElementsCsvReader, BadDirectIrradianceNamesFileAndLine) {
  const std::vector<Rgb> direct = {Rgb(1, 2, 3), Rgb(4, 5, 6)};
  const std::vector<uint64_t> buried = {5, 6};
  for (const bool withBuried : {false, true}) {
    SCOPED_TRACE(withBuried ? "with buried_cells" : "without buried_cells");
    std::ostringstream good;
    writeElementsCsv(good, unitSquare(), std::vector<Rgb>(2, Rgb::all(1)),
                     withBuried ? &buried : nullptr, &direct);
    const std::string text = good.str();
    const std::string header = text.substr(0, text.find('\n') + 1);
    const std::string rows = text.substr(header.size());
    const std::string row0 = rows.substr(0, rows.find('\n') + 1);
    const std::string row1 = rows.substr(row0.size());
    // Row 1's fields, and a row of fields joined again.
    auto row1Fields = [&] {
      std::vector<std::string> f;
      std::istringstream fields(row1.substr(0, row1.find('\n')));
      for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
      return f;
    };
    auto joined = [](const std::vector<std::string>& f) {
      std::string out;
      for (size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
      return out + "\n";
    };
    // The file with row 1's (line 3's) Ed field `k` (0..2) replaced.
    auto withEd = [&](int k, const std::string& value) {
      std::vector<std::string> f = row1Fields();
      f[static_cast<size_t>(16 + k)] = value;
      return header + row0 + joined(f);
    };
    auto expectError = [](const std::string& content, const std::string& message) {
      std::istringstream in(content);
      try {
        readElementsCsv(in, "sol.csv");
        ADD_FAILURE() << "no error for: " << content;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      }
    };
    // The unchanged file reads, so that each error below is the change's.
    {
      std::istringstream in(withEd(0, "4"));
      EXPECT_EQ(readElementsCsv(in, "sol.csv").rows[1].directIrradiance.r, 4.0);
    }
    expectError(withEd(0, "-1"),
                "sol.csv:3: Ed_r (direct irradiance) must be non-negative, not '-1'");
    expectError(withEd(2, "-1e-300"),
                "sol.csv:3: Ed_b (direct irradiance) must be non-negative, not '-1e-300'");
    expectError(withEd(1, "x"), "sol.csv:3: not a finite number: 'x'");
    expectError(withEd(1, "nan"), "sol.csv:3: not a finite number: 'nan'");
    expectError(withEd(2, "inf"), "sol.csv:3: not a finite number: 'inf'");
    expectError(withEd(0, ""), "sol.csv:3: not a finite number: ''");
    // A row without the Ed columns under the header with them, and one with a field too many.
    const size_t expected = withBuried ? 20 : 19;
    const std::string count = "expected " + std::to_string(expected) + " comma-separated fields";
    std::vector<std::string> withoutEd = row1Fields();
    withoutEd.erase(withoutEd.begin() + 16, withoutEd.begin() + 19);
    expectError(header + row0 + joined(withoutEd),
                "sol.csv:3: " + count + ", found " + std::to_string(expected - 3));
    expectError(header + row0 + row1.substr(0, row1.size() - 1) + ",0\n",
                "sol.csv:3: " + count + ", found " + std::to_string(expected + 1));
    // Rows with the Ed columns under a header without them.
    expectError(std::string(kElementsCsvHeader) + (withBuried ? ",buried_cells\n" : "\n") + row0,
                "sol.csv:2: expected " + std::to_string(withBuried ? 17 : 16));
  }
  // Headers out of order or incomplete are not elements CSVs.
  for (const std::string& header :
       {std::string(kElementsCsvHeader) + ",buried_cells,Ed_r,Ed_g,Ed_b",
        std::string(kElementsCsvHeader) + ",Ed_r,Ed_g",
        std::string(kElementsCsvHeader) + ",Ed_r,Ed_g,Ed_b,",
        std::string(kElementsCsvHeader) + ",Ed_b,Ed_g,Ed_r"}) {
    std::istringstream in(header + "\n");
    try {
      readElementsCsv(in, "sol.csv");
      ADD_FAILURE() << "no error for: " << header;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("sol.csv:1: not an elements CSV"), std::string::npos)
          << e.what();
    }
  }
}

TEST(ElementsCsvReader, BadBuriedCellsNameFileAndLine) {
  const std::vector<uint64_t> buried = {5, 6};
  std::ostringstream good;
  writeElementsCsv(good, unitSquare(), std::vector<Rgb>(2, Rgb::all(1)), &buried);
  const std::string text = good.str();
  const std::string header = text.substr(0, text.find('\n') + 1);
  const std::string row0 =
      text.substr(header.size(), text.find('\n', header.size()) - header.size());
  const std::string withoutMask = row0.substr(0, row0.rfind(',') + 1);
  for (const std::string bad : {"", "0x5", "-1", "g", "1ffffffffffffffff", "5 ", " 5", "+5"}) {
    std::istringstream in(header + withoutMask + bad + "\n");
    try {
      readElementsCsv(in, "sol.csv");
      ADD_FAILURE() << "no error for '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("sol.csv:2: buried_cells must be a 64-bit mask in "
                                           "hexadecimal (1 to 16 digits), not '" +
                                           bad + "'"),
                std::string::npos)
          << e.what();
    }
  }
  // A row without the column under a header with it, and one with it under a header without.
  std::istringstream shortRow(header + withoutMask.substr(0, withoutMask.size() - 1) + "\n");
  EXPECT_THROW(readElementsCsv(shortRow, "sol.csv"), InputError);
  std::istringstream longRow(std::string(kElementsCsvHeader) + "\n" + row0 + "\n");
  EXPECT_THROW(readElementsCsv(longRow, "sol.csv"), InputError);
  // Upper-case digits read as well (a hand-edited file).
  std::istringstream upper(header + withoutMask + "FF\n");
  EXPECT_EQ(readElementsCsv(upper, "sol.csv").rows[0].buriedCells, 0xffu);
}

// Bad input: an InputError naming the file and the line.
TEST(ElementsCsvReader, BadInputNamesFileAndLine) {
  std::ostringstream good;
  writeElementsCsv(good, unitSquare(), std::vector<Rgb>(2, Rgb::all(1)));
  const std::string text = good.str();
  const std::string header = text.substr(0, text.find('\n') + 1);
  const std::string row0 =
      text.substr(header.size(), text.find('\n', header.size()) + 1 - header.size());
  auto expectError = [](const std::string& content, const std::string& where,
                        const std::string& what) {
    std::istringstream in(content);
    try {
      readElementsCsv(in, "sol.csv");
      ADD_FAILURE() << "no error for: " << content;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  expectError("", "sol.csv:1:", "header missing");
  expectError("element,patch\n" + row0, "sol.csv:1:", "header missing");
  expectError(header + row0 + "0,0,0,1\n", "sol.csv:3:", "expected 16 comma-separated fields");
  expectError(header + "\n" + row0 + row0.substr(0, row0.size() - 1) + ",\n",
              "sol.csv:4:", "expected 16 comma-separated fields");
  std::string nan = row0;
  nan.replace(nan.rfind(','), std::string::npos, ",nan\n");
  expectError(header + nan, "sol.csv:2:", "not a finite number: 'nan'");
  expectError(header + "1e999" + row0.substr(row0.find(',')),
              "sol.csv:2:", "not a finite number: '1e999'");
  expectError(header + "x" + row0.substr(row0.find(',')), "sol.csv:2:", "not a finite number: 'x'");
  expectError(header + "0.5" + row0.substr(row0.find(',')),
              "sol.csv:2:", "element must be a non-negative integer");
  // A missing file names it.
  try {
    readElementsCsv("/nonexistent/radiosity/elements.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/radiosity/elements.csv: cannot open"),
              std::string::npos)
        << e.what();
  }
  // CRLF line ends and empty lines read the same.
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::istringstream in(crlf + "\n");
  EXPECT_EQ(readElementsCsv(in, "sol.csv").rows.size(), 2u);
}

// Numbers in decimal notation as strtod reads them (a hand-edited file keeps working): a leading
// '+' and leading blanks are accepted, exponents too, and a value too small for a double reads as
// 0 as strtod gives it; trailing text, a lone or doubled sign, hexadecimal, infinities and an empty
// field are refused.
TEST(ElementsCsvReader, NumbersReadAsStrtodReadsThem) {
  std::ostringstream good;
  writeElementsCsv(good, unitSquare(), std::vector<Rgb>(2, Rgb::all(1)));
  const std::string text = good.str();
  const std::string header = text.substr(0, text.find('\n') + 1);
  // Row 0 with its radiosity fields (10..12) replaced.
  auto row = [&](const std::string& r, const std::string& g, const std::string& b) {
    std::istringstream first(text.substr(header.size()));
    std::string line;
    std::getline(first, line);
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    f[10] = r, f[11] = g, f[12] = b;
    std::string out;
    for (size_t k = 0; k < f.size(); ++k) out += (k ? "," : "") + f[k];
    return header + out + "\n";
  };
  std::istringstream accepted(row("+2.5", " \t3", "1.0e1") +
                              row("1e-400", "0", "0").substr(header.size()));
  const std::vector<ElementsCsvRow> rows = readElementsCsv(accepted, "sol.csv").rows;
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].radiosity.r, 2.5);
  EXPECT_EQ(rows[0].radiosity.g, 3.0);
  EXPECT_EQ(rows[0].radiosity.b, 10.0);
  EXPECT_EQ(rows[1].radiosity.r, std::strtod("1e-400", nullptr));
  EXPECT_LT(rows[1].radiosity.r, 1e-300);
  for (const std::string bad : {"2.5x", "+", "+-1", "--1", "0x10", "", "1 ", "inf", "-1e400"}) {
    std::istringstream in(row("1", bad, "1"));
    try {
      readElementsCsv(in, "sol.csv");
      ADD_FAILURE() << "no error for '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("sol.csv:2: not a finite number: '" + bad + "'"),
                std::string::npos)
          << e.what();
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Vertex colours PLY.

TEST(VertexColorsPly, UniformSquare) {
  const PatchMesh mesh = unitSquare();
  const VertexInterpolation vi(mesh);
  // B = π·(0.5, 0.25, 1): radiance (0.5, 0.25, 1), colours (188, 137, 255) at exposure 1.
  const std::vector<Rgb> b(2, Rgb(0.5 * kPi, 0.25 * kPi, kPi));
  const PlyFile ply = parsePly(writePly(mesh, vi, b, ToneMap{1.0}));

  ASSERT_EQ(ply.elements.size(), 2u);
  const PlyElement& vertices = ply.element("vertex");
  const PlyElement& faces = ply.element("face");
  std::vector<std::string> names;
  for (const auto& p : vertices.properties) names.push_back(p.type + " " + p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"float x", "float y", "float z", "float nx",
                                             "float ny", "float nz", "float radiance_r",
                                             "float radiance_g", "float radiance_b", "uchar red",
                                             "uchar green", "uchar blue"}));
  ASSERT_EQ(faces.properties.size(), 1u);
  EXPECT_TRUE(faces.properties[0].list);
  EXPECT_EQ(faces.properties[0].countType, "uchar");
  EXPECT_EQ(faces.properties[0].type, "int");
  EXPECT_EQ(faces.properties[0].name, "vertex_indices");

  ASSERT_EQ(vertices.count, 4);
  ASSERT_EQ(faces.count, 2);
  std::set<std::pair<double, double>> corners;
  for (const auto& v : vertices.scalars) {
    corners.insert({v.at("x"), v.at("y")});
    EXPECT_EQ(v.at("z"), 0.0);
    EXPECT_EQ(v.at("nx"), 0.0);
    EXPECT_EQ(v.at("ny"), 0.0);
    EXPECT_EQ(v.at("nz"), 1.0);
    EXPECT_EQ(v.at("radiance_r"), 0.5f);
    EXPECT_EQ(v.at("radiance_g"), 0.25f);
    EXPECT_EQ(v.at("radiance_b"), 1.0f);
    EXPECT_EQ(v.at("red"), 188);
    EXPECT_EQ(v.at("green"), 137);
    EXPECT_EQ(v.at("blue"), 255);
  }
  EXPECT_EQ(corners, (std::set<std::pair<double, double>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));

  // Each face lists its element's corners, in the element's winding.
  for (int e = 0; e < 2; ++e) {
    const auto& idx = faces.lists[e].at("vertex_indices");
    ASSERT_EQ(idx.size(), 3u);
    const auto c = mesh.corners(e);
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(idx[k], 0);
      ASSERT_LT(idx[k], vertices.count);
      const auto& v = vertices.scalars[idx[k]];
      EXPECT_EQ(Eigen::Vector3d(v.at("x"), v.at("y"), v.at("z")), c[k]);
    }
  }
}

TEST(VertexColorsPly, HeaderStatesUnitsAndExposure) {
  const PatchMesh mesh = unitSquare();
  const VertexInterpolation vi(mesh);
  const double exposure = 1.0 / 3.0;
  const PlyFile ply = parsePly(writePly(mesh, vi, std::vector<Rgb>(2), ToneMap{exposure}));
  bool units = false, exposureStated = false;
  for (const auto& c : ply.comments) {
    if (c.find("W m^-2 sr^-1") != std::string::npos) units = true;
    if (c.rfind("exposure ", 0) == 0 && std::stod(c.substr(9)) == exposure) exposureStated = true;
  }
  EXPECT_TRUE(units);
  EXPECT_TRUE(exposureStated);
}

TEST(VertexColorsPly, VerticesSplitAtMaterialsAndCreasesOnly) {
  struct Case {
    const char* what;
    PatchMesh mesh;
    int vertices;
  };
  // 6 mesh vertices; the 2 on the shared edge are split when the sides differ.
  const Case cases[] = {{"coplanar, one material", coplanarPair(0, 0), 6},
                        {"coplanar, two materials", coplanarPair(0, 1), 8},
                        {"folded 90 degrees, one material", foldedPair(0, 0), 8}};
  for (const Case& c : cases) {
    ASSERT_EQ(c.mesh.elementCount(), 4) << c.what;
    const VertexInterpolation vi(c.mesh);
    const PlyFile ply = parsePly(writePly(c.mesh, vi, std::vector<Rgb>(4, Rgb::all(1)), {}));
    EXPECT_EQ(ply.element("vertex").count, c.vertices) << c.what;
    EXPECT_EQ(ply.element("face").count, 4) << c.what;
  }
}

TEST(VertexColorsPly, MaterialBoundaryDoesNotBleed) {
  // Material 0 uniform B = π·0.2, material 1 uniform B = π·0.8: every vertex, including those on
  // the shared edge, carries its own side's radiance exactly.
  const PatchMesh mesh = coplanarPair(0, 1);
  ASSERT_EQ(mesh.elementCount(), 4);
  const VertexInterpolation vi(mesh);
  std::vector<Rgb> b(4);
  const double radiance[2] = {0.2, 0.8};
  for (int e = 0; e < 4; ++e) b[e] = Rgb::all(kPi * radiance[mesh.material(e)]);
  const PlyFile ply = parsePly(writePly(mesh, vi, b, ToneMap{1.0}));
  const PlyElement& vertices = ply.element("vertex");
  const PlyElement& faces = ply.element("face");
  ASSERT_EQ(faces.count, 4);
  for (int e = 0; e < 4; ++e)
    for (long v : faces.lists[e].at("vertex_indices")) {
      const auto& vertex = vertices.scalars.at(v);
      const float expected = static_cast<float>(radiance[mesh.material(e)]);
      EXPECT_EQ(vertex.at("radiance_r"), expected);
      EXPECT_EQ(vertex.at("radiance_g"), expected);
      EXPECT_EQ(vertex.at("radiance_b"), expected);
    }
}

TEST(VertexColorsPly, InterpolationIsAreaWeightedRadiance) {
  // Two equal-area triangles with B = π·(1, 0, 0.5) and π·(0, 1, 0.5): the two corners on the
  // diagonal see both (mean radiance (0.5, 0.5, 0.5)), the other two only their own triangle.
  const PatchMesh mesh = unitSquare();
  ASSERT_EQ(mesh.elementCount(), 2);
  const VertexInterpolation vi(mesh);
  const std::vector<Rgb> b = {kPi * Rgb(1, 0, 0.5), kPi * Rgb(0, 1, 0.5)};
  const std::vector<Rgb> l = interpolateVertexRadiance(vi, b);
  ASSERT_EQ(static_cast<int>(l.size()), vi.vertexCount());
  ASSERT_EQ(vi.vertexCount(), 4);
  std::vector<int> uses(4, 0), owner(4, -1);
  for (int e = 0; e < 2; ++e)
    for (int v : vi.triangle(e)) {
      ++uses[v];
      owner[v] = e;
    }
  int shared = 0;
  for (int v = 0; v < 4; ++v) {
    const Rgb expected = uses[v] == 2 ? Rgb(0.5, 0.5, 0.5) : b[owner[v]] / kPi;
    shared += uses[v] == 2;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[v][c], expected[c], 1e-15) << v << " " << c;
  }
  EXPECT_EQ(shared, 2);
}

TEST(VertexColorsPly, RejectsAWrongNumberOfValues) {
  const PatchMesh mesh = unitSquare();
  const VertexInterpolation vi(mesh);
  std::ostringstream out;
  EXPECT_THROW(writeVertexColorsPly(out, vi, mesh, std::vector<Rgb>(3), ToneMap{}), CheckFailure);
}

}  // namespace
}  // namespace rad
