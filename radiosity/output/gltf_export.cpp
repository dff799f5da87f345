#include "radiosity/output/gltf_export.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

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

  tinygltf::Model& model() { return model_; }

 private:
  tinygltf::Model model_;
};

}  // namespace

void writeBakedGlb(std::ostream& out, const BakedMesh& mesh, const BakedLook& look,
                   const ToneMap& toneMap, LightmapContent content) {
  const bool lightmap = !look.lightmapPages.empty();
  const bool textureUvs = !mesh.textureUvs.empty();
  if (lightmap) RAD_CHECK_EQ(mesh.uvs.size(), mesh.positions.size());  // one UV per vertex
  if (textureUvs) RAD_CHECK_EQ(mesh.textureUvs.size(), mesh.positions.size());
  if (!look.baseColours.empty()) RAD_CHECK_EQ(look.baseColours.size(), mesh.materialNames.size());
  // COLOR_0 multiplies the base colour (glTF 2.0, 3.7.2.1): where the base colour is the scene's,
  // the tone-mapped radiance would darken it, so the vertex colours stay in _RADIANCE only.
  const bool vertexColours = !lightmap || look.baseColours.empty();
  GlbBuilder b;
  tinygltf::Model& model = b.model();
  model.asset.version = "2.0";
  model.asset.generator = "radiosity bake";
  tinygltf::Value::Object info;
  info["radiance_unit"] = tinygltf::Value(std::string("W m^-2 sr^-1 (scene units in metres)"));
  info["exposure"] = tinygltf::Value(toneMap.exposure);
  if (vertexColours)
    info["COLOR_0"] = tinygltf::Value(std::string("clamp(exposure * radiance, 0, 1), linear"));
  info["_RADIANCE"] = tinygltf::Value(std::string("linear outgoing radiance"));
  if (lightmap) {
    info["lightmap_content"] = tinygltf::Value(lightmapContentName(content));
    info["lightmap"] = tinygltf::Value(lightmapContentMeaning(content) +
                                       std::string(" (emissiveTexture on TEXCOORD_1)"));
    info["lightmap_pages"] = tinygltf::Value(static_cast<int>(look.lightmapPages.size()));
  }
  tinygltf::Value::Object extras;
  extras["radiosity"] = tinygltf::Value(info);
  model.asset.extras = tinygltf::Value(extras);

  std::vector<float> positions, normals, colours, radiance, uvs, texUvs;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    Eigen::Vector3d n = mesh.normals[v];
    n = n.norm() > 0 ? Eigen::Vector3d(n.normalized())
                     : Eigen::Vector3d::UnitY();  // glTF wants unit normals
    for (int k = 0; k < 3; ++k) {
      positions.push_back(static_cast<float>(mesh.positions[v][k]));
      normals.push_back(static_cast<float>(n[k]));
      const double l = mesh.radiance[v][k];
      radiance.push_back(static_cast<float>(l));
      colours.push_back(
          static_cast<float>(std::clamp(std::isfinite(l) ? toneMap.exposure * l : 0.0, 0.0, 1.0)));
    }
    if (lightmap)
      uvs.push_back(static_cast<float>(mesh.uvs[v].x())),
          uvs.push_back(static_cast<float>(mesh.uvs[v].y()));
    if (textureUvs)
      texUvs.push_back(static_cast<float>(mesh.textureUvs[v].x())),
          texUvs.push_back(static_cast<float>(mesh.textureUvs[v].y()));
  }
  std::map<std::string, int> attributes{{"POSITION", b.addVec(positions, 3, true)},
                                        {"NORMAL", b.addVec(normals, 3, false)},
                                        {"_RADIANCE", b.addVec(radiance, 3, false)}};
  if (vertexColours) attributes["COLOR_0"] = b.addVec(colours, 3, false);
  for (size_t i = 0; i < look.layers.size(); ++i) {
    const BakedLayer& layer = look.layers[i];
    RAD_CHECK_EQ(layer.radiance.size(), mesh.positions.size());
    std::vector<float> values;
    for (const Rgb& l : layer.radiance)
      for (int k = 0; k < 3; ++k) values.push_back(static_cast<float>(l[k]));
    attributes["_LIGHT_GROUP_" + std::to_string(i)] = b.addVec(values, 3, false);
  }
  if (lightmap) attributes["TEXCOORD_0"] = attributes["TEXCOORD_1"] = b.addVec(uvs, 2, false);
  if (textureUvs) attributes["TEXCOORD_0"] = b.addVec(texUvs, 2, false);

  auto addTexture = [&](const std::string& name, const std::string& mimeType,
                        const std::vector<std::uint8_t>& bytes, int sampler) {
    tinygltf::Image image;
    image.name = name;
    image.mimeType = mimeType;
    image.bufferView = b.addView(bytes.data(), bytes.size(), 0);
    model.bufferViews.back().target = 0;  // image data is not a vertex or index buffer
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model.images.size()) - 1;
    texture.sampler = sampler;
    model.textures.push_back(texture);
    return static_cast<int>(model.textures.size()) - 1;
  };
  std::vector<int> lightmapTexture, baseColourTexture;
  if (lightmap) {
    tinygltf::Sampler sampler;
    // Bilinear without mipmaps: the padding keeps one chart from bleeding into another at this
    // level only.
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    model.samplers.push_back(sampler);
    for (size_t p = 0; p < look.lightmapPages.size(); ++p)
      lightmapTexture.push_back(
          addTexture(look.lightmapPages.size() == 1 ? "lightmap" : "lightmap_" + std::to_string(p),
                     "image/png", look.lightmapPages[p], 0));
    if (!look.images.empty()) {
      tinygltf::Sampler repeat;  // scene textures tile (repeat wrap, glTF's default), mipmapped
      repeat.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
      repeat.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
      model.samplers.push_back(repeat);
      for (const EncodedImage& image : look.images)
        baseColourTexture.push_back(addTexture(image.name, image.mimeType, image.bytes, 1));
    }
  } else {
    model.extensionsUsed.push_back("KHR_materials_unlit");
  }
  if (!look.layers.empty()) {
    tinygltf::Value::Array groups;
    for (size_t i = 0; i < look.layers.size(); ++i) {
      const BakedLayer& layer = look.layers[i];
      tinygltf::Value::Object group;
      group["name"] = tinygltf::Value(layer.name);
      group["attribute"] = tinygltf::Value("_LIGHT_GROUP_" + std::to_string(i));
      tinygltf::Value::Array textures, exrs;
      for (size_t p = 0; p < layer.lightmapPages.size(); ++p)
        textures.emplace_back(addTexture(
            "lightmap_" + layer.name +
                (layer.lightmapPages.size() == 1 ? std::string() : "_" + std::to_string(p)),
            "image/png", layer.lightmapPages[p], 0));
      for (const std::string& file : layer.exrFiles) exrs.emplace_back(file);
      group["lightmap_textures"] = tinygltf::Value(textures);
      group["lightmap_exr"] = tinygltf::Value(exrs);
      groups.emplace_back(group);
    }
    info["light_groups"] = tinygltf::Value(groups);
    info["light_groups_rule"] = tinygltf::Value(std::string(
        "the layers are linear: sum(weight_i * layer_i) relights the scene with group i scaled by "
        "weight_i; weights of 1 give _RADIANCE and the lightmap"));
    extras["radiosity"] = tinygltf::Value(info);
    model.asset.extras = tinygltf::Value(extras);
  }

  tinygltf::Mesh gltfMesh;
  gltfMesh.name = "baked";
  const int pages = lightmap ? static_cast<int>(look.lightmapPages.size()) : 1;
  for (int page = 0; page < pages; ++page)
    for (size_t m = 0; m < mesh.materialNames.size(); ++m) {
      std::vector<std::uint32_t> indices;
      for (size_t t = 0; t < mesh.triangles.size(); ++t)
        if (mesh.materials[t] == static_cast<int>(m) && mesh.pages[t] == page)
          for (int k = 0; k < 3; ++k)
            indices.push_back(static_cast<std::uint32_t>(mesh.triangles[t][k]));
      if (indices.empty()) continue;
      tinygltf::Material material;
      material.name = mesh.materialNames[m] + (pages > 1 ? "_page" + std::to_string(page) : "");
      material.pbrMetallicRoughness.metallicFactor = 0;
      material.pbrMetallicRoughness.roughnessFactor = 1;
      if (lightmap) {
        material.pbrMetallicRoughness.baseColorFactor = {0, 0, 0, 1};
        if (!look.baseColours.empty()) {
          const BaseColour& base = look.baseColours[m];
          material.pbrMetallicRoughness.baseColorFactor = {base.factor.r, base.factor.g,
                                                           base.factor.b, 1};
          if (base.image >= 0) {
            RAD_CHECK_LT(base.image, static_cast<int>(baseColourTexture.size()));
            material.pbrMetallicRoughness.baseColorTexture.index = baseColourTexture[base.image];
            material.pbrMetallicRoughness.baseColorTexture.texCoord = 0;
          }
        }
        material.emissiveTexture.index = lightmapTexture[page];
        // The lightmap set, as engines expect. Blender's importer maps it to the UV map
        // "UVMap.001".
        material.emissiveTexture.texCoord = 1;
        material.emissiveFactor = {1, 1, 1};
      } else {
        material.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
        material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
      }
      model.materials.push_back(material);
      tinygltf::Primitive primitive;
      primitive.attributes = attributes;
      primitive.indices = b.addIndices(indices);
      primitive.material = static_cast<int>(model.materials.size()) - 1;
      primitive.mode = TINYGLTF_MODE_TRIANGLES;
      gltfMesh.primitives.push_back(primitive);
    }
  model.meshes.push_back(gltfMesh);
  tinygltf::Node node;
  node.name = "baked";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.buffers[0].uri.clear();

  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw RuntimeFailure("tinygltf could not serialise the baked scene");
}

}  // namespace rad
