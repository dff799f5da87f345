#pragma once
// Writes a Scene as glTF 2.0 for the tests (tinygltf's writer): each polygon fanned into
// triangles, one mesh per material, all under one node whose transform is `transform`; the
// vertices are written through its inverse, so the world-space scene is unchanged. Emission is
// written as a colour of maximum 1 times KHR_materials_emissive_strength.
#include <tiny_gltf.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <cstring>
#include <string>
#include <vector>

#include "radiosity/scene/scene.h"

namespace rad::test {

// The scene as fanned triangles, in the order the writer emits them (materials in order, then
// polygons in order), each material's triangles sharing vertices among themselves only (a glTF
// primitive per material, as the writer makes): the flattened reference a glTF reader must
// reproduce, connectivity included.
inline Scene fanTriangulated(const Scene& scene) {
  Scene out = scene;
  out.polygons.clear();
  out.positions.clear();
  for (int m = 0; m < static_cast<int>(scene.materials.size()); ++m) {
    std::vector<int> copy(scene.positions.size(), -1);  // scene vertex → this material's copy
    auto vertex = [&](int v) {
      if (copy[v] < 0) {
        copy[v] = static_cast<int>(out.positions.size());
        out.positions.push_back(scene.positions[v]);
      }
      return copy[v];
    };
    for (const ScenePolygon& p : scene.polygons) {
      if (p.material != m) continue;
      for (std::size_t i = 1; i + 1 < p.vertices.size(); ++i) {
        ScenePolygon t;
        t.material = m;
        t.vertices = {vertex(p.vertices[0]), vertex(p.vertices[i]), vertex(p.vertices[i + 1])};
        out.polygons.push_back(t);
      }
    }
  }
  return out;
}

inline int addBufferView(tinygltf::Model& model, const void* data, std::size_t bytes) {
  auto& buffer = model.buffers[0].data;
  while (buffer.size() % 4) buffer.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  const auto* p = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), p, p + bytes);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

inline int addAccessor(tinygltf::Model& model, const std::vector<float>& values, int type,
                       int components) {
  tinygltf::Accessor a;
  a.bufferView = addBufferView(model, values.data(), values.size() * sizeof(float));
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.count = values.size() / components;
  a.type = type;
  if (components == 3) {
    a.minValues = {1e30, 1e30, 1e30};
    a.maxValues = {-1e30, -1e30, -1e30};
    for (std::size_t i = 0; i < values.size(); ++i) {
      a.minValues[i % 3] = std::min<double>(a.minValues[i % 3], values[i]);
      a.maxValues[i % 3] = std::max<double>(a.maxValues[i % 3], values[i]);
    }
  }
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size()) - 1;
}

inline tinygltf::Model gltfModel(const Scene& scene, const Eigen::Matrix4d& transform) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.emplace_back();
  model.extensionsUsed.push_back("KHR_materials_emissive_strength");
  const Eigen::Matrix4d inverse = transform.inverse();
  tinygltf::Node node;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) node.matrix.push_back(transform(r, c));
  const Scene triangles = fanTriangulated(scene);
  for (int m = 0; m < static_cast<int>(scene.materials.size()); ++m) {
    const Material& source = scene.materials[m];
    tinygltf::Material material;
    material.name = source.name;
    material.pbrMetallicRoughness.baseColorFactor = {source.diffuse.r, source.diffuse.g,
                                                     source.diffuse.b, 1};
    material.pbrMetallicRoughness.metallicFactor = 0;
    material.pbrMetallicRoughness.roughnessFactor = 1;
    const double strength = source.emission.maxComponent();
    if (strength > 0) {
      material.emissiveFactor = {source.emission.r / strength, source.emission.g / strength,
                                 source.emission.b / strength};
      tinygltf::Value::Object ext;
      ext["emissiveStrength"] = tinygltf::Value(strength);
      material.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
    }
    model.materials.push_back(material);

    // This material's vertices are contiguous in `triangles` (fanTriangulated numbers them so).
    int first = -1, last = -1;
    std::vector<std::uint32_t> indices;
    for (const ScenePolygon& t : triangles.polygons) {
      if (t.material != m) continue;
      for (int v : t.vertices) {
        first = first < 0 ? v : std::min(first, v);
        last = std::max(last, v);
      }
    }
    if (first < 0) continue;
    for (const ScenePolygon& t : triangles.polygons)
      if (t.material == m)
        for (int v : t.vertices) indices.push_back(static_cast<std::uint32_t>(v - first));
    std::vector<float> positions;
    for (int v = first; v <= last; ++v) {
      const Eigen::Vector4d local = inverse * triangles.positions[v].homogeneous();
      for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(local[k]));
    }
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = addAccessor(model, positions, TINYGLTF_TYPE_VEC3, 3);
    tinygltf::Accessor index;
    index.bufferView = addBufferView(model, indices.data(), indices.size() * 4);
    index.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    index.count = indices.size();
    index.type = TINYGLTF_TYPE_SCALAR;
    model.accessors.push_back(index);
    primitive.indices = static_cast<int>(model.accessors.size()) - 1;
    primitive.material = m;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = source.name;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node child;
    child.mesh = static_cast<int>(model.meshes.size()) - 1;
    model.nodes.push_back(child);
    node.children.push_back(static_cast<int>(model.nodes.size()) - 1);
  }
  model.nodes.push_back(node);
  tinygltf::Scene s;
  s.nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
  model.scenes.push_back(s);
  model.defaultScene = 0;
  return model;
}

// Writes `model` to `path` (.glb: binary; .gltf: JSON with its buffer in `<stem>.bin`).
inline bool writeGltf(tinygltf::Model model, const std::string& path) {
  const bool binary = path.size() > 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  if (!binary) {
    const std::string name = path.substr(path.find_last_of('/') + 1);
    model.buffers[0].uri = name.substr(0, name.find_last_of('.')) + ".bin";
  }
  tinygltf::TinyGLTF writer;
  return writer.WriteGltfSceneToFile(&model, path, false, binary, true, binary);
}

}  // namespace rad::test
