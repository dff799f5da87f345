#include "radiosity/pipeline/kept_factors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <future>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <type_traits>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"
#include "radiosity/pipeline/fingerprint.h"
#include "radiosity/pipeline/resource_limits.h"

namespace rad {
namespace {

constexpr const char* kMagic = "radiosity kept factors 2\n";
constexpr const char* kOlderMagic = "radiosity kept factors 1\n";
constexpr uint64_t kMaxHeaderBytes = 1 << 24;

// The file's bytes gathered into large chunks before they reach the stream: written row by row
// (a few kilobytes each), a large scene's factors.bin took 134,000 write calls and over a second.
class ChunkedWriter {
 public:
  explicit ChunkedWriter(std::ostream& out) : out_(out) { buffer_.reserve(kChunk); }
  void bytes(const void* data, size_t count) {
    if (buffer_.size() + count > kChunk) flush();
    const char* p = static_cast<const char*>(data);
    if (count >= kChunk) {
      out_.write(p, static_cast<std::streamsize>(count));
      return;
    }
    buffer_.insert(buffer_.end(), p, p + count);
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr size_t kChunk = size_t{4} << 20;
  std::ostream& out_;
  std::vector<char> buffer_;
};

template <typename T>
void put(ChunkedWriter& out, const T& value) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.bytes(&value, sizeof(T));  // little-endian hosts only
}

template <typename T>
void putArray(ChunkedWriter& out, const T* values, size_t count) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.bytes(values, count * sizeof(T));
}

template <typename T>
void putArray(ChunkedWriter& out, const std::vector<T>& values) {
  putArray(out, values.data(), values.size());
}

// Reads the file's parts in order; every read that falls short names the part and the file.
class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw InputError(path, 0, "cannot open the kept form factors");
    in_.seekg(0, std::ios::end);
    size_ = static_cast<uint64_t>(in_.tellg());
    in_.seekg(0);
  }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, 0, what); }
  uint64_t left() const { return size_ - offset_; }
  void bytes(void* to, uint64_t n, const std::string& what) {
    if (n > left())
      fail("cut short in " + what + " (the file ends at byte " + std::to_string(size_) + ")");
    in_.read(static_cast<char*>(to), static_cast<std::streamsize>(n));
    if (!in_) fail("cannot read " + what);
    offset_ += n;
  }
  template <typename T>
  T get(const std::string& what) {
    T value;
    bytes(&value, sizeof(T), what);
    return value;
  }
  template <typename T>
  std::vector<T> array(uint64_t count, const std::string& what) {
    std::vector<T> values;
    arrayInto(values, count, what);
    return values;
  }
  // Into `values`, reused across calls (the rows: no allocation per row).
  template <typename T>
  void arrayInto(std::vector<T>& values, uint64_t count, const std::string& what) {
    if (count > left() / sizeof(T)) fail("cut short in " + what);
    values.resize(count);
    bytes(values.data(), count * sizeof(T), what);
  }

 private:
  std::string path_;
  std::ifstream in_;
  uint64_t size_ = 0, offset_ = 0;
};

bool finiteNonNegative(double x) { return std::isfinite(x) && x >= 0; }

// j[key] as a T: a JSON integer in T's range. (json::get<T> would cast a fraction or a number
// past T's range, which for a float is undefined behaviour.)
template <typename T>
T integerAt(const nlohmann::json& j, const char* key, const Reader& reader) {
  const nlohmann::json& v = j.at(key);
  bool ok = false;
  if (v.is_number_unsigned()) {
    ok = v.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<T>::max());
  } else if (v.is_number_integer()) {
    const auto s = v.get<int64_t>();
    ok = s >= 0 ? static_cast<uint64_t>(s) <= static_cast<uint64_t>(std::numeric_limits<T>::max())
                : std::is_signed_v<T> && s >= static_cast<int64_t>(std::numeric_limits<T>::min());
  }
  if (!ok)
    reader.fail(std::string("the header's \"") + key +
                "\" is not an integer in range: " + v.dump());
  return v.is_number_unsigned() ? static_cast<T>(v.get<uint64_t>())
                                : static_cast<T>(v.get<int64_t>());
}

nlohmann::json optionsJson(const SolveOptions& o) {
  return {{"max_area", o.maxArea},
          {"element_size", o.elementSize},
          {"elements", o.targetElements},
          {"two_sided", o.twoSided.all},
          {"two_sided_materials", o.twoSided.materials},
          {"rays", o.raysPerElement},
          {"seed", o.seed},
          {"solver", solverKindName(o.solver)},
          {"tolerance", o.tolerance},
          {"max_iterations", o.maxIterations}};
}

SolveOptions optionsFromJson(const nlohmann::json& j, const Reader& reader) {
  SolveOptions o;
  try {
    o.maxArea = j.at("max_area").get<double>();
    o.elementSize = j.at("element_size").get<double>();
    o.targetElements = integerAt<int>(j, "elements", reader);
    o.twoSided.all = j.at("two_sided").get<bool>();
    o.twoSided.materials = j.at("two_sided_materials").get<std::vector<std::string>>();
    o.raysPerElement = integerAt<int>(j, "rays", reader);
    o.seed = integerAt<uint64_t>(j, "seed", reader);
    o.solver = parseSolverKind(j.at("solver").get<std::string>());
    o.tolerance = j.at("tolerance").get<double>();
    o.maxIterations = integerAt<int>(j, "max_iterations", reader);
  } catch (const nlohmann::json::exception& e) {
    reader.fail(std::string("the header's options are incomplete: ") + e.what());
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;  // integerAt's, naming the file already
    reader.fail(std::string("the header's options are not valid: ") + e.what());  // the solver
  }
  o.keepFactors = true;
  try {
    validateSolveOptions(o);
  } catch (const InputError& e) {
    reader.fail(std::string("the header's options are not valid: ") + e.what());
  }
  return o;
}

// The shortcuts --sky and --sun as the command line gave them, in order (the kept lights' order).
nlohmann::json lightInputJson(const LightInput& input) {
  nlohmann::json shortcuts = nlohmann::json::array();
  for (const Light& l : input.shortcuts) {
    if (l.type == LightType::Sky)
      shortcuts.push_back({{"sky", {l.radiance.r, l.radiance.g, l.radiance.b}}});
    else
      shortcuts.push_back({{"sun",
                            {l.direction.x(), l.direction.y(), l.direction.z(), l.irradiance.r,
                             l.irradiance.g, l.irradiance.b}}});
  }
  return {{"file", input.file}, {"shortcuts", shortcuts}};
}

LightInput lightInputFromJson(const nlohmann::json& j, const Reader& reader) {
  LightInput input;
  input.file = j.at("file").get<std::string>();
  for (const nlohmann::json& s : j.at("shortcuts")) {
    try {
      if (s.contains("sky")) {
        const auto v = s.at("sky").get<std::vector<double>>();
        if (v.size() != 3) reader.fail("the header's sky shortcut needs 3 numbers");
        input.shortcuts.push_back(skyLight({v[0], v[1], v[2]}));
      } else {
        const auto v = s.at("sun").get<std::vector<double>>();
        if (v.size() != 6) reader.fail("the header's sun shortcut needs 6 numbers");
        Light sun = sunLight({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
        sun.direction = {v[0], v[1], v[2]};  // normalised once already: not again, bit for bit
        input.shortcuts.push_back(sun);
      }
    } catch (const InputError& e) {
      if (!e.file().empty()) throw;
      reader.fail(std::string("the header's light shortcuts are not valid: ") + e.what());
    }
  }
  return input;
}

// What of material m decides which rays it stops or bends, in two parts so that the scene's
// fingerprint keeps the order it had before the visibility was hashed on its own (kept files
// stay valid): its kind, specular values, two-sidedness and cut-out settings ...
void addMaterialKind(Fingerprint& f, const Material& m) {
  f.add(static_cast<int>(m.kind));
  f.add(m.specular);
  f.add(m.transmittance);
  f.add(m.ior);
  f.add(m.twoSided);
  f.add(m.alphaTexture);
  f.add(m.alphaFromDiffuse);
  f.add(m.alphaCutoff);
}

// ... and its cut-out mask's texels (a mask texture's alpha is geometry here).
void addCutoutMask(Fingerprint& f, const Scene& scene, const Material& m) {
  const int mask = m.alphaTexture >= 0  ? m.alphaTexture
                   : m.alphaFromDiffuse ? m.diffuseTexture
                                        : -1;
  if (mask >= 0 && mask < static_cast<int>(scene.textures.size())) {
    const Texture& t = scene.textures[static_cast<size_t>(mask)];
    f.add(t.width);
    f.add(t.height);
    for (size_t i = 0; i < t.rgba.size(); ++i) f.add(t.rgba[i]);
  }
}

}  // namespace

std::map<std::string, std::string> keptMaterialVisibility(const Scene& scene) {
  std::map<std::string, std::string> byName;
  for (const Material& m : scene.materials) {
    Fingerprint f;
    addMaterialKind(f, m);
    addCutoutMask(f, scene, m);
    byName[m.name] = f.hex();
  }
  return byName;
}

std::string keptFactorsFingerprint(const Scene& scene, const SolveOptions& o) {
  Fingerprint f;
  f.add(std::string(kMagic));
  addGeometry(f, scene);
  f.add(scene.materials.size());
  for (const Material& m : scene.materials) {
    f.add(m.name);
    addMaterialKind(f, m);
    f.add(m.diffuseTexture);
    f.add(m.emissionTexture);
    addCutoutMask(f, scene, m);
  }
  f.add(o.raysPerElement);
  f.add(o.maxArea);
  f.add(o.targetElements);
  f.add(o.elementSize);
  f.add(o.seed);
  f.add(o.twoSided.all);
  for (const std::string& m : o.twoSided.materials) f.add(m);
  return f.hex();
}

void writeKeptFactors(std::ostream& stream, const KeptFactors& kept) {
  ChunkedWriter out(stream);
  const size_t n = kept.area.size();
  nlohmann::json lights = nlohmann::json::array();
  for (size_t l = 0; l < kept.lightGroups.size(); ++l)
    lights.push_back({{"type", kept.lightTypes[l]}, {"group", kept.lightGroups[l]}});
  const std::string header = nlohmann::json{
      {"scene", kept.scenePath},
      {"fingerprint", kept.fingerprint},
      {"elements", n},
      {"lights", lights},
      {"options", optionsJson(kept.options)},
      {"element_edge", kept.elementEdge},
      {"light_input", lightInputJson(kept.lightInput)},
      {"lights_fingerprint", kept.lightsFingerprint},
      {"materials_fingerprint", kept.materialsFingerprint},
      {"material_visibility",
       kept.materialVisibility}}.dump();
  out.bytes(kMagic, std::strlen(kMagic));
  put(out, static_cast<uint64_t>(header.size()));
  out.bytes(header.data(), header.size());
  putArray(out, kept.area);
  for (const std::vector<Rgb>& irradiance : kept.lightIrradiance) {
    std::vector<double> values;
    for (const Rgb& e : irradiance) values.insert(values.end(), {e.r, e.g, e.b});
    putArray(out, values);
  }
  std::vector<float> values, tinted;
  static_assert(sizeof(int) == sizeof(int32_t));
  for (size_t i = 0; i < kept.rows.size(); ++i) {
    const KeptRowTable::RowView row = kept.rows.view(i);
    put(out, static_cast<uint32_t>(row.count));
    put(out, static_cast<uint8_t>(!row.tinted.empty()));
    put(out, row.escaped);
    putArray(out, row.targets, row.count);
    values.assign(row.values, row.values + row.count);
    putArray(out, values);
    if (row.tinted.empty()) continue;
    tinted.clear();
    for (const Rgb& t : row.tinted)
      tinted.insert(tinted.end(),
                    {static_cast<float>(t.r), static_cast<float>(t.g), static_cast<float>(t.b)});
    putArray(out, tinted);
  }
  RAD_CHECK(kept.corners.size() == n && kept.material.size() == n && kept.patch.size() == n &&
            kept.rayMultiplier.size() == n);
  std::vector<double> corners;
  corners.reserve(9 * n);
  for (const auto& c : kept.corners)
    for (const Eigen::Vector3d& p : c) corners.insert(corners.end(), {p.x(), p.y(), p.z()});
  putArray(out, corners);
  putArray(out, std::vector<int32_t>(kept.material.begin(), kept.material.end()));
  putArray(out, std::vector<int32_t>(kept.patch.begin(), kept.patch.end()));
  std::vector<uint8_t> multiplier;
  for (int m : kept.rayMultiplier) multiplier.push_back(static_cast<uint8_t>(m));
  putArray(out, multiplier);
  out.flush();
}

KeptFactors readKeptFactors(const std::string& path, KeptParts parts) {
  Reader reader(path);
  std::string magic(std::strlen(kMagic), '\0');
  reader.bytes(magic.data(), magic.size(), "the first line");
  if (magic == kOlderMagic)
    reader.fail(
        "kept by an older version of radiosity (format 1, without the mesh that update "
        "needs): solve --keep-factors again");
  if (magic != kMagic)
    reader.fail("not a kept form factors file (it starts with \"radiosity kept factors 2\")");
  const auto headerBytes = reader.get<uint64_t>("the header's length");
  if (headerBytes > kMaxHeaderBytes || headerBytes > reader.left())
    reader.fail("the header's length " + std::to_string(headerBytes) + " is past the file's end");
  std::string text(headerBytes, '\0');
  reader.bytes(text.data(), headerBytes, "the header");
  KeptFactors kept;
  uint64_t n = 0;
  try {
    const nlohmann::json header = nlohmann::json::parse(text);
    kept.scenePath = header.at("scene").get<std::string>();
    kept.fingerprint = header.at("fingerprint").get<std::string>();
    n = integerAt<uint64_t>(header, "elements", reader);
    for (const nlohmann::json& light : header.at("lights")) {
      kept.lightTypes.push_back(light.at("type").get<std::string>());
      kept.lightGroups.push_back(light.at("group").get<std::string>());
    }
    kept.options = optionsFromJson(header.at("options"), reader);
    kept.elementEdge = header.at("element_edge").get<double>();
    kept.lightInput = lightInputFromJson(header.at("light_input"), reader);
    kept.lightsFingerprint = header.value("lights_fingerprint", std::string());
    kept.materialsFingerprint = header.value("materials_fingerprint", std::string());
    kept.materialVisibility =
        header.value("material_visibility", std::map<std::string, std::string>());
  } catch (const nlohmann::json::exception& e) {
    reader.fail(std::string("the header is not the expected JSON: ") + e.what());
  }
  if (n > static_cast<uint64_t>(kMaxElements))
    reader.fail(std::to_string(n) + " elements: more than a solve makes (" +
                std::to_string(static_cast<uint64_t>(kMaxElements)) + ")");
  kept.options.scenePath = kept.scenePath;
  // Checked with the header: `update` meshes with it before the rest is read.
  if (!(kept.elementEdge > 0) || !std::isfinite(kept.elementEdge))
    reader.fail("the header's element_edge must be a positive number");
  if (parts == KeptParts::Header) return kept;
  kept.area = reader.array<double>(n, "the areas");
  for (double a : kept.area)
    if (!finiteNonNegative(a)) reader.fail("an element's area is negative or not finite");
  for (size_t l = 0; l < kept.lightGroups.size(); ++l) {
    const std::vector<double> values =
        reader.array<double>(3 * n, "light " + std::to_string(l) + "'s irradiance");
    std::vector<Rgb>& irradiance = kept.lightIrradiance.emplace_back(n);
    for (size_t i = 0; i < n; ++i) {
      irradiance[i] = {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
      if (!irradiance[i].isFinite() || irradiance[i].minComponent() < 0)
        reader.fail("light " + std::to_string(l) + "'s irradiance is negative or not finite");
    }
  }
  // Each row takes at least 13 bytes: the header's count allocates no more rows than the file
  // holds.
  if (n > reader.left() / 13) reader.fail("cut short in the rows");
  // Each factor takes at least 8 bytes: what is left bounds the factors to reserve.
  kept.rows.reserve(n, reader.left() / 8);
  // The fresh pages are cleared on a second thread while this one reads into them.
  std::future<void> populating =
      std::async(std::launch::async, [&rows = kept.rows] { rows.populateReserved(); });
  std::vector<int32_t> targets;
  std::vector<float> values, tinted;
  for (size_t i = 0; i < n; ++i) {
    const std::string what = "row " + std::to_string(i);
    const auto count = reader.get<uint32_t>(what);
    const auto isTinted = reader.get<uint8_t>(what);
    const auto escaped = reader.get<double>(what);
    if (count > n || isTinted > 1 || !finiteNonNegative(escaped))
      reader.fail(what + ": not a form-factor row (" + std::to_string(count) + " targets)");
    reader.arrayInto(targets, count, what);
    reader.arrayInto(values, count, what);
    double sum = 0;
    for (uint32_t k = 0; k < count; ++k) {
      if (targets[k] < 0 || static_cast<uint64_t>(targets[k]) >= n ||
          (k > 0 && targets[k] <= targets[k - 1]) || !finiteNonNegative(values[k]))
        reader.fail(what + ": targets must be increasing element indices and factors finite, >= 0");
      sum += values[k];
    }
    if (sum > 1 + 1e-4) reader.fail(what + ": its factors sum past 1");
    std::vector<Rgb> tintedFactors;
    if (isTinted) {
      reader.arrayInto(tinted, 3 * static_cast<uint64_t>(count), what);
      for (uint32_t k = 0; k < count; ++k) {
        tintedFactors.push_back({tinted[3 * k], tinted[3 * k + 1], tinted[3 * k + 2]});
        if (!tintedFactors.back().isFinite() || tintedFactors.back().minComponent() < 0)
          reader.fail(what + ": tinted factors must be finite, >= 0");
      }
    }
    kept.rows.appendRow(targets.data(), values.data(), count, escaped, std::move(tintedFactors));
  }
  const std::vector<double> corners = reader.array<double>(9 * n, "the mesh's corners");
  kept.corners.resize(n);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) {
      const double* p = &corners[9 * i + 3 * static_cast<size_t>(c)];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        reader.fail("element " + std::to_string(i) + "'s corners are not finite");
      kept.corners[i][c] = {p[0], p[1], p[2]};
    }
  const std::vector<int32_t> material = reader.array<int32_t>(n, "the mesh's materials");
  const std::vector<int32_t> patch = reader.array<int32_t>(n, "the mesh's patches");
  const std::vector<uint8_t> multiplier = reader.array<uint8_t>(n, "the rows' ray multipliers");
  for (size_t i = 0; i < n; ++i)
    if (material[i] < 0 || patch[i] < 0 || multiplier[i] < 1 || multiplier[i] > 64)
      reader.fail("element " + std::to_string(i) +
                  ": a negative material or patch, or a ray multiplier outside 1..64");
  kept.material.assign(material.begin(), material.end());
  kept.patch.assign(patch.begin(), patch.end());
  kept.rayMultiplier.assign(multiplier.begin(), multiplier.end());
  if (reader.left() != 0)
    reader.fail(std::to_string(reader.left()) + " bytes after the mesh: not one kept solve");
  return kept;
}

std::string keptMaterialsFingerprint(const Scene& scene) {
  Fingerprint f;
  f.add(scene.materials.size());
  for (const Material& m : scene.materials) {
    f.add(m.name);
    f.add(m.diffuse);
    f.add(m.emission);
    f.add(m.diffuseTexture);
    f.add(m.emissionTexture);
  }
  addTextures(f, scene);
  return f.hex();
}

std::string keptLightsFingerprint(const std::vector<Light>& lights) {
  Fingerprint f;
  addLights(f, lights);
  return f.hex();
}

}  // namespace rad
