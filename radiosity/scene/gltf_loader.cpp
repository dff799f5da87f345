#include "radiosity/scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "radiosity/core/errors.h"
#include "radiosity/core/log.h"
#include "radiosity/scene/gltf_accessor.h"

namespace rad {
namespace {

namespace fs = std::filesystem;

// The extensions whose meaning this reader implements; any other one in extensionsRequired
// makes the file unreadable as its author meant it.
const std::set<std::string> kSupportedExtensions = {
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_materials_transmission",
    "KHR_materials_ior"};

// A metallic-roughness material this metallic and this smooth is a mirror; anything else is
// diffuse with its base colour as reflectance.
constexpr double kMirrorMinMetallic = 0.9;
constexpr double kMirrorMaxRoughness = 0.1;
// glTF's default index of refraction (KHR_materials_ior).
constexpr double kDefaultIor = 1.5;
// Triangles below this fraction of the squared bounding-box diagonal in area are degenerate (as
// the OBJ reader's rule: relative, so it means the same at any scale).
constexpr double kDegenerateAreaFraction = 1e-12;
// The image height a glTF camera gets; its aspect ratio sets the width.
constexpr int kCameraHeight = 256;

[[noreturn]] void fail(const std::string& file, const std::string& pointer,
                       const std::string& what) {
  throw InputError(file, 0, pointer + ": " + what);
}

// --- the file before tinygltf: JSON checks that name the pointer -------------------------------

std::string readWhole(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open glTF file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool isBinary(const std::string& bytes) { return bytes.compare(0, 4, "glTF") == 0; }

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
  return v;
}

// The JSON text of a .gltf, or the JSON chunk of a .glb.
std::string jsonText(const std::string& bytes, const std::string& path) {
  if (!isBinary(bytes)) return bytes;
  if (bytes.size() < 20) throw InputError(path, 0, "binary glTF shorter than its 20-byte header");
  if (le32(bytes, 4) != 2)
    throw InputError(
        path, 0,
        "binary glTF version " + std::to_string(le32(bytes, 4)) + ": radiosity reads version 2");
  const std::uint32_t length = le32(bytes, 12);
  if (le32(bytes, 16) != 0x4E4F534Au || length > bytes.size() - 20)
    throw InputError(path, 0, "binary glTF: the first chunk is not a JSON chunk inside the file");
  return bytes.substr(20, length);
}

// %XX escapes of a URI, as glTF allows in file names.
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// Unsupported required extensions and external files that are not there, named by pointer
// before tinygltf's own messages (which name neither the pointer nor the file) could.
void checkJson(const nlohmann::json& j, const std::string& path) {
  if (!j.is_object()) throw InputError(path, 0, "a glTF file holds one JSON object");
  if (j.contains("extensionsRequired") && j["extensionsRequired"].is_array()) {
    const nlohmann::json& required = j["extensionsRequired"];
    for (std::size_t i = 0; i < required.size(); ++i) {
      const std::string name = required[i].is_string() ? required[i].get<std::string>() : "?";
      if (!kSupportedExtensions.count(name))
        fail(path, "/extensionsRequired/" + std::to_string(i),
             "required extension " + name + " is not supported (radiosity reads " +
                 "KHR_lights_punctual, KHR_materials_emissive_strength, "
                 "KHR_materials_transmission, KHR_materials_ior)");
    }
  }
  if (j.contains("extensionsUsed") && j["extensionsUsed"].is_array())
    for (const nlohmann::json& used : j["extensionsUsed"])
      if (used.is_string() && !kSupportedExtensions.count(used.get<std::string>()))
        logInfo(path + ": extension " + used.get<std::string>() +
                " (used, not required) is ignored");
  const fs::path dir = fs::path(path).parent_path();
  for (const char* list : {"buffers", "images"}) {
    if (!j.contains(list) || !j[list].is_array()) continue;
    for (std::size_t i = 0; i < j[list].size(); ++i) {
      const nlohmann::json& item = j[list][i];
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      if (uri.compare(0, 5, "data:") == 0) continue;
      const fs::path file = dir / percentDecoded(uri);
      std::error_code error;
      if (!fs::is_regular_file(file, error))
        fail(path, "/" + std::string(list) + "/" + std::to_string(i) + "/uri",
             "cannot read " + std::string(list[0] == 'b' ? "buffer" : "image") + " file " +
                 file.string());
    }
  }
}

// An unsigned integer member of `object` (or `fallback` when absent); anything else is an error.
std::uint64_t unsignedMember(const nlohmann::json& object, const char* key, std::uint64_t fallback,
                             const std::string& path, const std::string& pointer) {
  if (!object.is_object() || !object.contains(key)) return fallback;
  const nlohmann::json& v = object[key];
  if (!v.is_number_unsigned()) fail(path, pointer + "/" + key, "must be an unsigned integer");
  return v.get<std::uint64_t>();
}

// tinygltf hands an image stored in a buffer view to the image callback as a pointer and a
// length it does not check against the buffer: they are checked here, against the buffer's
// byteLength (which tinygltf does hold the data to).
void checkImageViews(const nlohmann::json& j, const std::string& path) {
  if (!j.contains("images") || !j["images"].is_array()) return;
  const nlohmann::json& views = j.contains("bufferViews") ? j["bufferViews"] : nlohmann::json();
  const nlohmann::json& buffers = j.contains("buffers") ? j["buffers"] : nlohmann::json();
  for (std::size_t i = 0; i < j["images"].size(); ++i) {
    const std::string pointer = "/images/" + std::to_string(i);
    const nlohmann::json& image = j["images"][i];
    if (!image.is_object() || !image.contains("bufferView")) continue;
    const std::uint64_t view = unsignedMember(image, "bufferView", 0, path, pointer);
    if (!views.is_array() || view >= views.size())
      fail(path, pointer + "/bufferView",
           "buffer view " + std::to_string(view) + " does not exist");
    const std::string viewPointer = "/bufferViews/" + std::to_string(view);
    const nlohmann::json& v = views[view];
    const std::uint64_t buffer = unsignedMember(v, "buffer", UINT64_MAX, path, viewPointer);
    if (!buffers.is_array() || buffer >= buffers.size())
      fail(path, viewPointer + "/buffer", "the buffer does not exist");
    const std::string bufferPointer = "/buffers/" + std::to_string(buffer);
    const std::uint64_t size =
        unsignedMember(buffers[buffer], "byteLength", 0, path, bufferPointer);
    const std::uint64_t offset = unsignedMember(v, "byteOffset", 0, path, viewPointer);
    const std::uint64_t length = unsignedMember(v, "byteLength", 0, path, viewPointer);
    if (offset > size || length > size - offset || length > 0x7FFFFFFFu)
      fail(path, viewPointer,
           "bytes " + std::to_string(offset) + " + " + std::to_string(length) +
               " run past the end of buffer " + std::to_string(buffer) + " (" +
               std::to_string(size) + " bytes)");
  }
}

// tinygltf hands each image's encoded bytes here; they are decoded later, once it is known
// whether the image holds colour (sRGB) or data.
bool keepEncodedBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

tinygltf::Model parseModel(const std::string& path) {
  const std::string bytes = readWhole(path);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(jsonText(bytes, path));
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers out of range
    throw InputError(path, 0, std::string("not valid glTF JSON: ") + e.what());
  }
  checkJson(j, path);
  checkImageViews(j, path);

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keepEncodedBytes, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const std::string dir = fs::path(path).parent_path().string();
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() > 0xFFFFFFFFu) throw InputError(path, 0, "glTF file larger than 4 GiB");
  const bool ok = isBinary(bytes)
                      ? loader.LoadBinaryFromMemory(&model, &error, &warning, data,
                                                    static_cast<unsigned>(bytes.size()), dir)
                      : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                                   static_cast<unsigned>(bytes.size()), dir);
  if (!warning.empty()) logDebug(path + ": tinygltf: " + warning);
  if (!ok) {
    while (!error.empty() && error.back() == '\n') error.pop_back();
    throw InputError(path, 0, "tinygltf cannot read the file: " + error);
  }
  return model;
}

// --- transforms -----------------------------------------------------------------------------

Eigen::Matrix4d localTransform(const tinygltf::Node& node, const std::string& path,
                               const std::string& pointer) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (node.matrix.size() == 16) {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m(r, c) = node.matrix[4 * c + r];  // column-major
  } else {
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    if (node.translation.size() == 3)
      t.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4) {
      Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      if (!(q.norm() > 0)) fail(path, pointer + "/rotation", "zero quaternion");
      t.rotate(q.normalized());
    }
    if (node.scale.size() == 3)
      t.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
    m = t.matrix();
  }
  if (!m.allFinite()) fail(path, pointer, "transform is not finite");
  return m;
}

// Each node of the default scene with its world transform, parents before children.
struct PlacedNode {
  int node;
  Eigen::Matrix4d world;
};

std::vector<PlacedNode> placeNodes(const tinygltf::Model& model, const std::string& path) {
  std::vector<PlacedNode> placed;
  if (model.scenes.empty()) return placed;
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size())
    fail(path, "/scene", "scene " + std::to_string(sceneIndex) + " does not exist");
  std::vector<bool> seen(model.nodes.size(), false);
  // Depth-first with an explicit stack: a deep hierarchy cannot overflow the call stack, and a
  // node reached twice (a cycle, or a shared child) is an error, as glTF requires a forest.
  std::vector<std::pair<int, Eigen::Matrix4d>> stack;
  const std::vector<int>& roots = model.scenes[sceneIndex].nodes;
  for (auto r = roots.rbegin(); r != roots.rend(); ++r)
    stack.emplace_back(*r, Eigen::Matrix4d::Identity());
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    const std::string pointer = "/nodes/" + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size())
      fail(path, pointer, "node " + std::to_string(index) + " does not exist");
    if (seen[index]) fail(path, pointer, "node is reached twice in the scene's hierarchy");
    seen[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    const Eigen::Matrix4d world = parent * localTransform(node, path, pointer);
    placed.push_back({index, world});
    for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
      stack.emplace_back(*c, world);
  }
  return placed;
}

// --- materials and textures -------------------------------------------------------------------

double numberOr(const tinygltf::Value& object, const char* key, double fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

const tinygltf::Value* extension(const tinygltf::ExtensionMap& map, const char* name) {
  const auto it = map.find(name);
  return it == map.end() ? nullptr : &it->second;
}

class MaterialReader {
 public:
  MaterialReader(const tinygltf::Model& model, const std::string& path, Scene& scene,
                 UnreadableTextures unreadable)
      : model_(model), path_(path), scene_(scene), unreadable_(unreadable) {}

  Material read(int index) {
    const tinygltf::Material& m = model_.materials[index];
    const std::string pointer = "/materials/" + std::to_string(index);
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    Material material;
    material.name = m.name.empty() ? "material " + std::to_string(index) : m.name;
    material.sourceFile = path_ + "#" + pointer;
    const Rgb base = colour(pbr.baseColorFactor, pointer + "/pbrMetallicRoughness/baseColorFactor");
    for (double c : pbr.baseColorFactor)
      if (!(c >= 0 && c <= 1))
        fail(path_, pointer + "/pbrMetallicRoughness/baseColorFactor",
             "reflectance must be in [0, 1] in every channel");

    Rgb emissive = colour(m.emissiveFactor, pointer + "/emissiveFactor");
    double strength = 1;
    if (const tinygltf::Value* e = extension(m.extensions, "KHR_materials_emissive_strength"))
      strength = numberOr(*e, "emissiveStrength", 1);
    if (!(std::isfinite(strength) && strength >= 0) || emissive.minComponent() < 0)
      fail(path_, pointer, "emission must be finite and non-negative");
    material.emission = emissive * strength;
    if (!material.emission.isFinite()) fail(path_, pointer, "emissive colour × strength overflows");
    if (m.emissiveTexture.index >= 0)
      material.emissionTexture = texture(m.emissiveTexture.index, m.emissiveTexture.texCoord,
                                         pointer + "/emissiveTexture");

    const double metallic = pbr.metallicFactor, roughness = pbr.roughnessFactor;
    if (!std::isfinite(metallic) || !std::isfinite(roughness))
      fail(path_, pointer + "/pbrMetallicRoughness", "metallic and roughness must be finite");
    double transmission = 0;
    if (const tinygltf::Value* t = extension(m.extensions, "KHR_materials_transmission"))
      transmission = numberOr(*t, "transmissionFactor", 0);
    material.ior = kDefaultIor;
    if (const tinygltf::Value* i = extension(m.extensions, "KHR_materials_ior"))
      material.ior = numberOr(*i, "ior", kDefaultIor);
    if (!(std::isfinite(transmission) && transmission >= 0 && transmission <= 1))
      fail(path_, pointer + "/extensions/KHR_materials_transmission",
           "transmissionFactor must be in [0, 1]");
    if (!(std::isfinite(material.ior) && material.ior >= 1))
      fail(path_, pointer + "/extensions/KHR_materials_ior", "ior must be finite and >= 1");

    if (transmission > 0) {
      material.kind = SurfaceKind::Dielectric;
      material.illum = 7;
      material.transmittance = base * transmission;
      material.specular = Rgb::all(1);
    } else if (metallic >= kMirrorMinMetallic && roughness <= kMirrorMaxRoughness) {
      material.kind = SurfaceKind::Mirror;
      material.illum = 3;
      material.specular = base;
    } else {
      material.diffuse = base;
      if (base.maxComponent() == 1)
        logWarning(path_ + ": " + pointer +
                   ": base colour 1 keeps all the light a surface receives; a closed scene of "
                   "such surfaces cannot converge (it stops at the iteration budget)");
      if (pbr.baseColorTexture.index >= 0)
        material.diffuseTexture = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                          pointer + "/pbrMetallicRoughness/baseColorTexture");
    }

    material.twoSided = m.doubleSided;
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
      if (m.alphaMode == "BLEND")
        logInfo(path_ + ": " + pointer +
                ": alphaMode BLEND is read as MASK at 0.5 (radiosity has cut-outs, not "
                "partial transparency)");
      material.alphaCutoff = m.alphaMode == "MASK" ? m.alphaCutoff : 0.5;
      if (!(material.alphaCutoff >= 0 && material.alphaCutoff <= 1))
        fail(path_, pointer + "/alphaCutoff", "must be in [0, 1]");
      material.alphaFromDiffuse = material.diffuseTexture >= 0;
      if (pbr.baseColorFactor.size() == 4 && pbr.baseColorFactor[3] < 1)
        logInfo(path_ + ": " + pointer +
                ": the alpha of baseColorFactor is not applied to cut-outs (only the texture's)");
    }
    return material;
  }

 private:
  Rgb colour(const std::vector<double>& values, const std::string& pointer) const {
    if (values.size() < 3) fail(path_, pointer, "needs at least 3 components");
    for (double v : values)
      if (!std::isfinite(v)) fail(path_, pointer, "must be finite");
    return {values[0], values[1], values[2]};
  }

  // The Scene's texture for glTF texture `index` (decoded once per image; colour maps are sRGB).
  int texture(int index, int texCoord, const std::string& pointer) {
    if (texCoord != 0)
      logWarning(path_ + ": " + pointer + ": texCoord " + std::to_string(texCoord) +
                 " is read as TEXCOORD_0 (radiosity textures use the first UV set)");
    if (index < 0 || static_cast<std::size_t>(index) >= model_.textures.size())
      fail(path_, pointer + "/index", "texture " + std::to_string(index) + " does not exist");
    const int image = model_.textures[index].source;
    const std::string texturePointer = "/textures/" + std::to_string(index) + "/source";
    if (image < 0 || static_cast<std::size_t>(image) >= model_.images.size())
      fail(path_, texturePointer, "image " + std::to_string(image) + " does not exist");
    const auto cached = decoded_.find(image);
    if (cached != decoded_.end()) return cached->second;

    const tinygltf::Image& img = model_.images[image];
    const std::string imagePointer = "/images/" + std::to_string(image);
    std::vector<unsigned char> bytes = img.image;
    std::string source = path_ + "#" + imagePointer;
    if (img.bufferView >= 0) {
      bytes = bufferViewBytes(model_, img.bufferView, path_);
    } else if (!img.uri.empty() && img.uri.compare(0, 5, "data:") != 0) {
      source = (fs::path(path_).parent_path() / percentDecoded(img.uri)).string();
    }
    if (bytes.empty()) fail(path_, imagePointer, "the image has no data");
    int id = -1;
    try {
      scene_.textures.push_back(
          decodeTexture(bytes.data(), bytes.size(), source, TextureEncoding::Srgb));
      id = static_cast<int>(scene_.textures.size()) - 1;
    } catch (const InputError& e) {
      if (unreadable_ == UnreadableTextures::Refuse) throw;
      const std::string what = path_ + ": " + imagePointer + ": " + e.what();
      logWarning(what + ": using the material's own colour instead (--strict makes this an error)");
      scene_.textureFallbacks.push_back(what);
    }
    decoded_[image] = id;  // warned once per image
    return id;
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  Scene& scene_;
  UnreadableTextures unreadable_;
  std::map<int, int> decoded_;  // glTF image → Scene texture (-1: not read)
};

Material defaultMaterial(const std::string& path) {
  Material material;
  material.name = "default";
  material.diffuse = Rgb::all(0.5);
  material.sourceFile = path;
  return material;
}

// --- geometry ----------------------------------------------------------------------------------

// The triangles of a primitive's vertex list, by mode; empty for points and lines.
std::vector<std::array<int, 3>> triangles(const std::vector<int>& order, int mode) {
  std::vector<std::array<int, 3>> out;
  const std::size_t n = order.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < n; i += 3)
      out.push_back({order[i], order[i + 1], order[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    // Every other triangle of a strip is wound the other way: swap two corners to keep the front.
    for (std::size_t i = 0; i + 2 < n; ++i)
      out.push_back(i % 2 == 0 ? std::array<int, 3>{order[i], order[i + 1], order[i + 2]}
                               : std::array<int, 3>{order[i + 1], order[i], order[i + 2]});
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 1; i + 1 < n; ++i) out.push_back({order[i], order[i + 1], order[0]});
  }
  return out;
}

std::vector<Eigen::Vector2d> readUvs(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                     const char* attribute, std::size_t count,
                                     const std::string& path, const std::string& pointer) {
  const auto it = p.attributes.find(attribute);
  if (it == p.attributes.end()) return {};
  const std::vector<double> values = readAccessor(model, it->second, 2, path);
  if (values.size() != 2 * count)
    fail(path, pointer + "/attributes/" + attribute, "has a different count than POSITION");
  std::vector<Eigen::Vector2d> uvs(count);
  // glTF's v runs down from the image's top; the Scene's runs up from its bottom.
  for (std::size_t i = 0; i < count; ++i) uvs[i] = {values[2 * i], 1 - values[2 * i + 1]};
  return uvs;
}

struct GeometryCounts {
  int skippedPrimitives = 0;  // points and lines
  int degenerate = 0;
};

void addPrimitive(const tinygltf::Model& model, int meshIndex, int primitiveIndex,
                  const Eigen::Matrix4d& world, const std::string& path,
                  const std::vector<int>& materialIds, int defaultMaterialId, Scene& scene,
                  GeometryCounts& counts) {
  const tinygltf::Primitive& p = model.meshes[meshIndex].primitives[primitiveIndex];
  const std::string pointer =
      "/meshes/" + std::to_string(meshIndex) + "/primitives/" + std::to_string(primitiveIndex);
  if (p.mode < 0) fail(path, pointer + "/mode", "unknown primitive mode " + std::to_string(p.mode));
  if (p.mode < TINYGLTF_MODE_TRIANGLES) {
    ++counts.skippedPrimitives;
    return;
  }
  if (p.mode > TINYGLTF_MODE_TRIANGLE_FAN)
    fail(path, pointer + "/mode", "unknown primitive mode " + std::to_string(p.mode));
  const auto position = p.attributes.find("POSITION");
  if (position == p.attributes.end())
    fail(path, pointer + "/attributes", "a triangle primitive needs POSITION");
  const std::vector<double> xyz = readAccessor(model, position->second, 3, path);
  const std::size_t count = xyz.size() / 3;
  const std::vector<Eigen::Vector2d> uvs = readUvs(model, p, "TEXCOORD_0", count, path, pointer);
  const std::vector<Eigen::Vector2d> lightmapUvs =
      readUvs(model, p, "TEXCOORD_1", count, path, pointer);

  std::vector<int> order;
  if (p.indices >= 0) {
    order = readIndices(model, p.indices, static_cast<int>(count), path);
  } else {
    for (std::size_t i = 0; i < count; ++i) order.push_back(static_cast<int>(i));
  }
  int material = defaultMaterialId;
  if (p.material >= 0) {
    if (static_cast<std::size_t>(p.material) >= materialIds.size())
      fail(path, pointer + "/material",
           "material " + std::to_string(p.material) + " does not exist");
    material = materialIds[p.material];
  }

  // A mirroring transform (negative determinant) would turn every front to the back.
  const bool mirrored = world.topLeftCorner<3, 3>().determinant() < 0;
  const int first = static_cast<int>(scene.positions.size());
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector4d v =
        world * Eigen::Vector4d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 1);
    if (!v.head<3>().allFinite())
      fail(path, pointer + "/attributes/POSITION", "a vertex is not finite after its transform");
    scene.positions.push_back(v.head<3>());
  }
  for (std::array<int, 3> t : triangles(order, p.mode)) {
    if (mirrored) std::swap(t[1], t[2]);
    ScenePolygon polygon;
    polygon.material = material;
    polygon.object = model.meshes[meshIndex].name;
    for (int v : t) {
      polygon.vertices.push_back(first + v);
      if (!uvs.empty()) polygon.uvs.push_back(uvs[v]);
      if (!lightmapUvs.empty()) polygon.lightmapUvs.push_back(lightmapUvs[v]);
    }
    scene.polygons.push_back(std::move(polygon));
  }
}

// Drops triangles with repeated corners or an area that is zero at the scene's scale.
void dropDegenerate(Scene& scene, GeometryCounts& counts) {
  if (scene.positions.empty()) return;
  Eigen::Vector3d lo = scene.positions.front(), hi = lo;
  for (const Eigen::Vector3d& p : scene.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal2 = (hi - lo).squaredNorm();
  std::vector<ScenePolygon> kept;
  kept.reserve(scene.polygons.size());
  for (ScenePolygon& polygon : scene.polygons) {
    const Eigen::Vector3d& a = scene.positions[polygon.vertices[0]];
    const Eigen::Vector3d& b = scene.positions[polygon.vertices[1]];
    const Eigen::Vector3d& c = scene.positions[polygon.vertices[2]];
    const bool repeated = a == b || b == c || a == c;
    if (repeated || 0.5 * (b - a).cross(c - a).norm() <= kDegenerateAreaFraction * diagonal2) {
      ++counts.degenerate;
      continue;
    }
    kept.push_back(std::move(polygon));
  }
  scene.polygons = std::move(kept);
}

// --- lights and cameras -------------------------------------------------------------------------

Light convertLight(const tinygltf::Model& model, int index, const Eigen::Matrix4d& world,
                   const std::string& path) {
  const std::string pointer = "/extensions/KHR_lights_punctual/lights/" + std::to_string(index);
  if (index < 0 || static_cast<std::size_t>(index) >= model.lights.size())
    fail(path, pointer, "light " + std::to_string(index) + " does not exist");
  const tinygltf::Light& l = model.lights[index];
  Rgb colour = Rgb::all(1);
  if (l.color.size() == 3) colour = {l.color[0], l.color[1], l.color[2]};
  if (!colour.isFinite() || colour.minComponent() < 0 || !std::isfinite(l.intensity) ||
      l.intensity < 0)
    fail(path, pointer, "colour and intensity must be finite and non-negative");
  if (l.range > 0)
    logInfo(path + ": " + pointer + ": range is ignored (lights fall off as 1/d² without a cut)");
  // Lights shine along their node's -z.
  const Eigen::Vector3d position = (world * Eigen::Vector4d(0, 0, 0, 1)).head<3>();
  const Eigen::Vector3d axis = world.topLeftCorner<3, 3>() * Eigen::Vector3d(0, 0, -1);
  if (!(axis.norm() > 0) || !axis.allFinite() || !position.allFinite())
    fail(path, pointer, "the node's transform gives the light no direction");
  Light light;
  light.group = l.name;
  light.position = position;
  light.direction = axis.normalized();
  const Rgb radiometric = colour * (l.intensity / kLumensPerWatt);
  if (l.type == "point") {
    light.type = LightType::Point;
    light.intensity = radiometric;
  } else if (l.type == "spot") {
    light.type = LightType::Spot;
    light.intensity = radiometric;
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!(inner >= 0 && outer > 0 && inner < outer && outer <= M_PI / 2))
      fail(path, pointer + "/spot", "cone angles need 0 <= inner < outer <= π/2");
    light.cosInner = std::cos(inner);
    light.cosOuter = std::cos(outer);
  } else if (l.type == "directional") {
    light.type = LightType::Directional;
    light.irradiance = radiometric;
  } else {
    fail(path, pointer + "/type", "unknown light type '" + l.type + "'");
  }
  return light;
}

// The KHR_lights_punctual light a node carries, if any.
std::optional<int> lightOf(const tinygltf::Node& node) {
  const tinygltf::Value* e = extension(node.extensions, "KHR_lights_punctual");
  if (!e || !e->IsObject() || !e->Has("light") || !e->Get("light").IsInt()) return std::nullopt;
  return e->Get("light").GetNumberAsInt();
}

}  // namespace

Scene loadGltfScene(const std::string& path, UnreadableTextures unreadable) {
  const tinygltf::Model model = parseModel(path);
  Scene scene;
  scene.sourcePath = path;

  MaterialReader reader(model, path, scene, unreadable);
  std::vector<int> materialIds;
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    scene.materials.push_back(reader.read(static_cast<int>(i)));
    materialIds.push_back(static_cast<int>(i));
  }
  const int defaultId = static_cast<int>(scene.materials.size());

  GeometryCounts counts;
  for (const PlacedNode& placed : placeNodes(model, path)) {
    const tinygltf::Node& node = model.nodes[placed.node];
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
        fail(path, "/nodes/" + std::to_string(placed.node) + "/mesh",
             "mesh " + std::to_string(node.mesh) + " does not exist");
      for (std::size_t p = 0; p < model.meshes[node.mesh].primitives.size(); ++p)
        addPrimitive(model, node.mesh, static_cast<int>(p), placed.world, path, materialIds,
                     defaultId, scene, counts);
    }
    if (const std::optional<int> light = lightOf(node))
      scene.lights.push_back(convertLight(model, *light, placed.world, path));
  }
  dropDegenerate(scene, counts);
  for (const ScenePolygon& polygon : scene.polygons)
    if (polygon.material == defaultId && !scene.usedDefaultMaterial) {
      scene.materials.push_back(defaultMaterial(path));
      scene.usedDefaultMaterial = true;
      logWarning(path +
                 ": some primitives have no material; using 'default', grey with "
                 "reflectance 0.5");
    }
  scene.skippedDegenerateFaces = counts.degenerate;
  if (counts.degenerate)
    logWarning(path + ": skipped " + std::to_string(counts.degenerate) +
               " degenerate triangle(s) with repeated corners or zero area");
  if (counts.skippedPrimitives)
    logInfo(path + ": skipped " + std::to_string(counts.skippedPrimitives) +
            " point or line primitive(s): only surfaces take part");
  logInfo("loaded " + path + ": " + std::to_string(scene.positions.size()) + " vertices, " +
          std::to_string(scene.polygons.size()) + " triangles, " +
          std::to_string(scene.materials.size()) + " materials, " +
          std::to_string(scene.emitterCount()) + " emitting triangles, " +
          std::to_string(scene.lights.size()) + " lights");
  return scene;
}

bool gltfSceneHasLights(const std::string& path) {
  const tinygltf::Model model = parseModel(path);
  for (const PlacedNode& placed : placeNodes(model, path))
    if (lightOf(model.nodes[placed.node])) return true;
  return false;
}

std::optional<Camera> loadGltfCamera(const std::string& path) {
  const tinygltf::Model model = parseModel(path);
  for (const PlacedNode& placed : placeNodes(model, path)) {
    const int index = model.nodes[placed.node].camera;
    if (index < 0) continue;
    const std::string pointer = "/cameras/" + std::to_string(index);
    if (static_cast<std::size_t>(index) >= model.cameras.size())
      fail(path, "/nodes/" + std::to_string(placed.node) + "/camera",
           "camera " + std::to_string(index) + " does not exist");
    const tinygltf::Camera& c = model.cameras[index];
    if (c.type != "perspective") {
      logInfo(path + ": " + pointer + ": only perspective cameras are read; skipped");
      continue;
    }
    Camera camera;
    const Eigen::Matrix3d linear = placed.world.topLeftCorner<3, 3>();
    camera.position = (placed.world * Eigen::Vector4d(0, 0, 0, 1)).head<3>();
    camera.lookAt = camera.position + linear * Eigen::Vector3d(0, 0, -1);
    camera.up = linear * Eigen::Vector3d(0, 1, 0);
    camera.vfovDegrees = c.perspective.yfov * 180 / M_PI;
    camera.height = kCameraHeight;
    camera.width =
        c.perspective.aspectRatio > 0
            ? std::max(1, static_cast<int>(std::lround(kCameraHeight * c.perspective.aspectRatio)))
            : kCameraHeight;
    validateCamera(camera, path + "#" + pointer);
    return camera;
  }
  return std::nullopt;
}

}  // namespace rad
