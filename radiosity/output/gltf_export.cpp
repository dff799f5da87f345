#include "radiosity/output/gltf_export.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "radiosity/core/check.h"
#include "radiosity/core/errors.h"

namespace rad {
namespace {

class GlbBuilder {
 public:
  GlbBuilder() { model_.buffers.emplace_back(); }

  int addView(const void* data, size_t bytes, int target) {
    auto& buffer = model_.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);  // accessors need 4-byte alignment
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  int addVec(const std::vector<float>& values, int components, bool minMax) {
    tinygltf::Accessor a;
    a.bufferView =
        addView(values.data(), values.size() * sizeof(float), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = values.size() / components;
    a.type = components == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
    if (minMax) {  // required for POSITION
      a.minValues.assign(components, INFINITY);
      a.maxValues.assign(components, -INFINITY);
      for (size_t i = 0; i < values.size(); ++i) {
        a.minValues[i % components] = std::min<double>(a.minValues[i % components], values[i]);
        a.maxValues[i % components] = std::max<double>(a.maxValues[i % components], values[i]);
      }
    }
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  int addIndices(const std::vector<std::uint32_t>& indices) {
    tinygltf::Accessor a;
    a.bufferView =
        addView(indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.count = indices.size();
    a.type = TINYGLTF_TYPE_SCALAR;
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  // An image in the buffer and the texture that samples it with sampler `sampler`.
  int addTexture(const std::string& name, const std::string& mimeType,
                 const std::vector<std::uint8_t>& bytes, int sampler) {
    tinygltf::Image image;
    image.name = name;
    image.mimeType = mimeType;
    image.bufferView = addView(bytes.data(), bytes.size(), 0);
    model_.bufferViews.back().target = 0;  // image data is not a vertex or index buffer
    model_.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model_.images.size()) - 1;
    texture.sampler = sampler;
    model_.textures.push_back(texture);
    return static_cast<int>(model_.textures.size()) - 1;
  }

  tinygltf::Model& model() { return model_; }

 private:
  tinygltf::Model model_;
};

// What the glb holds besides the mesh, and the options it was made with.
struct GlbLayout {
  bool lightmap;    // emissive lightmap pages on TEXCOORD_1 (else an unlit, vertex-coloured mesh)
  bool textureUvs;  // the scene's own texture coordinates on TEXCOORD_0
  bool vertexColours;  // COLOR_0
};

GlbLayout checkedLayout(const BakedMesh& mesh, const BakedLook& look) {
  GlbLayout layout;
  layout.lightmap = !look.lightmapPages.empty();
  layout.textureUvs = !mesh.textureUvs.empty();
  if (layout.lightmap) RAD_CHECK_EQ(mesh.uvs.size(), mesh.positions.size());  // one UV per vertex
  if (layout.textureUvs) RAD_CHECK_EQ(mesh.textureUvs.size(), mesh.positions.size());
  if (!look.baseColours.empty()) RAD_CHECK_EQ(look.baseColours.size(), mesh.materialNames.size());
  // COLOR_0 multiplies the base colour (glTF 2.0, 3.7.2.1): where the base colour is the scene's,
  // the tone-mapped radiance would darken it, so the vertex colours stay in _RADIANCE only.
  layout.vertexColours = !layout.lightmap || look.baseColours.empty();
  return layout;
}

// asset.extras.radiosity: what the attributes and the lightmap hold, in which units.
tinygltf::Value::Object describeOutputs(const GlbLayout& layout, const BakedLook& look,
                                        const ToneMap& toneMap, LightmapContent content) {
  tinygltf::Value::Object info;
  info["radiance_unit"] = tinygltf::Value(std::string("W m^-2 sr^-1 (scene units in metres)"));
  info["exposure"] = tinygltf::Value(toneMap.exposure);
  if (layout.vertexColours)
    info["COLOR_0"] = tinygltf::Value(std::string("clamp(exposure * radiance, 0, 1), linear"));
  info["_RADIANCE"] = tinygltf::Value(std::string("linear outgoing radiance"));
  if (layout.lightmap) {
    info["lightmap_content"] = tinygltf::Value(lightmapContentName(content));
    info["lightmap"] = tinygltf::Value(lightmapContentMeaning(content) +
                                       std::string(" (emissiveTexture on TEXCOORD_1)"));
    info["lightmap_pages"] = tinygltf::Value(static_cast<int>(look.lightmapPages.size()));
  }
  return info;
}

// The per-vertex arrays as glTF stores them: floats, unit normals, tone-mapped colours.
struct VertexArrays {
  std::vector<float> positions, normals, colours, radiance, uvs, texUvs;
};

VertexArrays vertexArrays(const BakedMesh& mesh, const GlbLayout& layout, const ToneMap& toneMap) {
  VertexArrays a;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    Eigen::Vector3d n = mesh.normals[v];
    n = n.norm() > 0 ? Eigen::Vector3d(n.normalized())
                     : Eigen::Vector3d::UnitY();  // glTF wants unit normals
    for (int k = 0; k < 3; ++k) {
      a.positions.push_back(static_cast<float>(mesh.positions[v][k]));
      a.normals.push_back(static_cast<float>(n[k]));
      const double l = mesh.radiance[v][k];
      a.radiance.push_back(static_cast<float>(l));
      a.colours.push_back(
          static_cast<float>(std::clamp(std::isfinite(l) ? toneMap.exposure * l : 0.0, 0.0, 1.0)));
    }
    if (layout.lightmap)
      a.uvs.push_back(static_cast<float>(mesh.uvs[v].x())),
          a.uvs.push_back(static_cast<float>(mesh.uvs[v].y()));
    if (layout.textureUvs)
      a.texUvs.push_back(static_cast<float>(mesh.textureUvs[v].x())),
          a.texUvs.push_back(static_cast<float>(mesh.textureUvs[v].y()));
  }
  return a;
}

// The vertex attributes every primitive shares, one accessor each (in this order in the buffer).
std::map<std::string, int> addAttributes(GlbBuilder& b, const VertexArrays& a,
                                         const GlbLayout& layout, const BakedMesh& mesh,
                                         const BakedLook& look) {
  std::map<std::string, int> attributes{{"POSITION", b.addVec(a.positions, 3, true)},
                                        {"NORMAL", b.addVec(a.normals, 3, false)},
                                        {"_RADIANCE", b.addVec(a.radiance, 3, false)}};
  if (layout.vertexColours) attributes["COLOR_0"] = b.addVec(a.colours, 3, false);
  // One linear radiance layer per light group, so that an engine can reweight the groups.
  for (size_t i = 0; i < look.layers.size(); ++i) {
    const BakedLayer& layer = look.layers[i];
    RAD_CHECK_EQ(layer.radiance.size(), mesh.positions.size());
    std::vector<float> values;
    for (const Rgb& l : layer.radiance)
      for (int k = 0; k < 3; ++k) values.push_back(static_cast<float>(l[k]));
    attributes["_LIGHT_GROUP_" + std::to_string(i)] = b.addVec(values, 3, false);
  }
  if (layout.lightmap)
    attributes["TEXCOORD_0"] = attributes["TEXCOORD_1"] = b.addVec(a.uvs, 2, false);
  if (layout.textureUvs) attributes["TEXCOORD_0"] = b.addVec(a.texUvs, 2, false);
  return attributes;
}

// Texture indices of the lightmap pages and of the scene's images (a base colour's `image`).
struct GlbTextures {
  std::vector<int> lightmap, baseColour;
};

// Sampler 0 for the lightmaps, sampler 1 for the scene's images; without a lightmap, no textures
// and an unlit mesh.
GlbTextures addLightmapAndImages(GlbBuilder& b, const BakedLook& look, bool lightmap) {
  tinygltf::Model& model = b.model();
  GlbTextures textures;
  if (!lightmap) {
    model.extensionsUsed.push_back("KHR_materials_unlit");
    return textures;
  }
  tinygltf::Sampler sampler;
  // Bilinear without mipmaps: the padding keeps one chart from bleeding into another at this
  // level only.
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  model.samplers.push_back(sampler);
  for (size_t p = 0; p < look.lightmapPages.size(); ++p)
    textures.lightmap.push_back(
        b.addTexture(look.lightmapPages.size() == 1 ? "lightmap" : "lightmap_" + std::to_string(p),
                     "image/png", look.lightmapPages[p], 0));
  if (!look.images.empty()) {
    tinygltf::Sampler repeat;  // scene textures tile (repeat wrap, glTF's default), mipmapped
    repeat.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    repeat.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    model.samplers.push_back(repeat);
    for (const EncodedImage& image : look.images)
      textures.baseColour.push_back(b.addTexture(image.name, image.mimeType, image.bytes, 1));
  }
  return textures;
}

// extras.radiosity.light_groups: per group its _LIGHT_GROUP_i attribute, its lightmap pages (as
// textures no material uses) and its EXR files beside the glb.
tinygltf::Value::Array addLightGroups(GlbBuilder& b, const BakedLook& look) {
  tinygltf::Value::Array groups;
  for (size_t i = 0; i < look.layers.size(); ++i) {
    const BakedLayer& layer = look.layers[i];
    tinygltf::Value::Object group;
    group["name"] = tinygltf::Value(layer.name);
    group["attribute"] = tinygltf::Value("_LIGHT_GROUP_" + std::to_string(i));
    tinygltf::Value::Array textures, exrs;
    for (size_t p = 0; p < layer.lightmapPages.size(); ++p)
      textures.emplace_back(b.addTexture(
          "lightmap_" + layer.name +
              (layer.lightmapPages.size() == 1 ? std::string() : "_" + std::to_string(p)),
          "image/png", layer.lightmapPages[p], 0));
    for (const std::string& file : layer.exrFiles) exrs.emplace_back(file);
    group["lightmap_textures"] = tinygltf::Value(textures);
    group["lightmap_exr"] = tinygltf::Value(exrs);
    groups.emplace_back(group);
  }
  return groups;
}

// Material m on lightmap page `page`: the lightmap as emission over a black (or the scene's) base
// colour, or, without a lightmap, unlit white so that COLOR_0 shows as is.
tinygltf::Material bakedMaterial(const BakedMesh& mesh, const BakedLook& look,
                                 const GlbTextures& textures, bool lightmap, size_t m, int page,
                                 int pages) {
  tinygltf::Material material;
  material.name = mesh.materialNames[m] + (pages > 1 ? "_page" + std::to_string(page) : "");
  material.pbrMetallicRoughness.metallicFactor = 0;
  material.pbrMetallicRoughness.roughnessFactor = 1;
  if (!lightmap) {
    material.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
    material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    return material;
  }
  material.pbrMetallicRoughness.baseColorFactor = {0, 0, 0, 1};
  if (!look.baseColours.empty()) {
    const BaseColour& base = look.baseColours[m];
    material.pbrMetallicRoughness.baseColorFactor = {base.factor.r, base.factor.g, base.factor.b,
                                                     1};
    if (base.image >= 0) {
      RAD_CHECK_LT(base.image, static_cast<int>(textures.baseColour.size()));
      material.pbrMetallicRoughness.baseColorTexture.index = textures.baseColour[base.image];
      material.pbrMetallicRoughness.baseColorTexture.texCoord = 0;
    }
  }
  material.emissiveTexture.index = textures.lightmap[page];
  // The lightmap set, as engines expect. Blender's importer maps it to the UV map "UVMap.001".
  material.emissiveTexture.texCoord = 1;
  material.emissiveFactor = {1, 1, 1};
  return material;
}

// The vertex indices of the triangles of material m on lightmap page `page`.
std::vector<std::uint32_t> triangleIndices(const BakedMesh& mesh, size_t m, int page) {
  std::vector<std::uint32_t> indices;
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    if (mesh.materials[t] == static_cast<int>(m) && mesh.pages[t] == page)
      for (int k = 0; k < 3; ++k)
        indices.push_back(static_cast<std::uint32_t>(mesh.triangles[t][k]));
  return indices;
}

// One primitive, with its own material, per (lightmap page, material) that has triangles: a
// material is one texture set, so each page needs its own.
tinygltf::Mesh bakedGltfMesh(GlbBuilder& b, const BakedMesh& mesh, const BakedLook& look,
                             const GlbTextures& textures, bool lightmap,
                             const std::map<std::string, int>& attributes) {
  tinygltf::Model& model = b.model();
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = "baked";
  const int pages = lightmap ? static_cast<int>(look.lightmapPages.size()) : 1;
  for (int page = 0; page < pages; ++page)
    for (size_t m = 0; m < mesh.materialNames.size(); ++m) {
      std::vector<std::uint32_t> indices = triangleIndices(mesh, m, page);
      if (indices.empty()) continue;
      model.materials.push_back(bakedMaterial(mesh, look, textures, lightmap, m, page, pages));
      tinygltf::Primitive primitive;
      primitive.attributes = attributes;
      primitive.indices = b.addIndices(indices);
      primitive.material = static_cast<int>(model.materials.size()) - 1;
      primitive.mode = TINYGLTF_MODE_TRIANGLES;
      gltfMesh.primitives.push_back(primitive);
    }
  return gltfMesh;
}

// Scene 0 (the default) holds node 0, which holds mesh 0.
void addSceneOfMesh(tinygltf::Model& model, tinygltf::Mesh mesh) {
  model.meshes.push_back(std::move(mesh));
  tinygltf::Node node;
  node.name = "baked";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
}

}  // namespace

// The buffer holds, in this order: the vertex attributes, the lightmap pages and scene images, the
// light groups' lightmap pages, then each primitive's indices.
void writeBakedGlb(std::ostream& out, const BakedMesh& mesh, const BakedLook& look,
                   const ToneMap& toneMap, LightmapContent content) {
  const GlbLayout layout = checkedLayout(mesh, look);
  GlbBuilder b;
  tinygltf::Model& model = b.model();
  model.asset.version = "2.0";
  model.asset.generator = "radiosity bake";
  tinygltf::Value::Object info = describeOutputs(layout, look, toneMap, content);

  const std::map<std::string, int> attributes =
      addAttributes(b, vertexArrays(mesh, layout, toneMap), layout, mesh, look);
  const GlbTextures textures = addLightmapAndImages(b, look, layout.lightmap);
  if (!look.layers.empty()) {
    info["light_groups"] = tinygltf::Value(addLightGroups(b, look));
    info["light_groups_rule"] = tinygltf::Value(std::string(
        "the layers are linear: sum(weight_i * layer_i) relights the scene with group i scaled by "
        "weight_i; weights of 1 give _RADIANCE and the lightmap"));
  }
  tinygltf::Value::Object extras;
  extras["radiosity"] = tinygltf::Value(info);
  model.asset.extras = tinygltf::Value(extras);

  addSceneOfMesh(model, bakedGltfMesh(b, mesh, look, textures, layout.lightmap, attributes));
  model.buffers[0].uri.clear();

  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw RuntimeFailure("tinygltf could not serialise the baked scene");
}

}  // namespace rad
