#include "radiosity/scene/gltf_accessor.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& pointer,
                       const std::string& what) {
  throw InputError(file, 0, pointer + ": " + what);
}

std::string accessorPointer(int index) { return "/accessors/" + std::to_string(index); }

int componentBytes(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

int typeComponents(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

// One component at `p` (little-endian, as glTF stores it).
template <typename T>
T load(const unsigned char* p) {
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}

double component(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? load<std::uint8_t>(p) / 255.0 : load<std::uint8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return normalized ? load<std::uint16_t>(p) / 65535.0 : load<std::uint16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return normalized ? std::max(load<std::int8_t>(p) / 127.0, -1.0) : load<std::int8_t>(p);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return normalized ? std::max(load<std::int16_t>(p) / 32767.0, -1.0) : load<std::int16_t>(p);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return load<std::uint32_t>(p);
    default:
      return load<std::int32_t>(p);
  }
}

// The checked location of an accessor's elements: where the first one starts and the distance
// between them.
struct Layout {
  const unsigned char* first = nullptr;
  std::size_t stride = 0;
  std::size_t count = 0;
  int componentType = 0;
  int components = 0;
  bool normalized = false;
};

// The view's bytes within its buffer.
const unsigned char* viewStart(const tinygltf::Model& model, int view, const std::string& file,
                               const std::string& user) {
  const std::string pointer = "/bufferViews/" + std::to_string(view);
  if (view < 0 || static_cast<std::size_t>(view) >= model.bufferViews.size())
    fail(file, user, "buffer view " + std::to_string(view) + " does not exist");
  const tinygltf::BufferView& v = model.bufferViews[view];
  if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model.buffers.size())
    fail(file, pointer + "/buffer", "buffer " + std::to_string(v.buffer) + " does not exist");
  const std::size_t size = model.buffers[v.buffer].data.size();
  if (v.byteOffset > size || v.byteLength > size - v.byteOffset)
    fail(file, pointer,
         "bytes " + std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
             " run past the end of buffer " + std::to_string(v.buffer) + " (" +
             std::to_string(size) + " bytes)");
  return model.buffers[v.buffer].data.data() + v.byteOffset;
}

Layout layoutOf(const tinygltf::Model& model, int index, const std::string& file) {
  const std::string pointer = accessorPointer(index);
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    fail(file, pointer, "accessor " + std::to_string(index) + " does not exist");
  const tinygltf::Accessor& a = model.accessors[index];
  if (a.sparse.isSparse) fail(file, pointer + "/sparse", "sparse accessors are not supported");
  if (a.bufferView < 0) fail(file, pointer, "an accessor without a bufferView is not supported");
  Layout layout;
  layout.componentType = a.componentType;
  layout.components = typeComponents(a.type);
  layout.normalized = a.normalized;
  layout.count = a.count;
  const int bytes = componentBytes(a.componentType);
  if (bytes == 0)
    fail(file, pointer + "/componentType",
         "unknown component type " + std::to_string(a.componentType));
  if (layout.components == 0) fail(file, pointer + "/type", "unsupported accessor type");
  const std::size_t elementBytes = static_cast<std::size_t>(bytes) * layout.components;
  const unsigned char* start = viewStart(model, a.bufferView, file, pointer + "/bufferView");
  const tinygltf::BufferView& view = model.bufferViews[a.bufferView];
  layout.stride = view.byteStride ? view.byteStride : elementBytes;
  if (layout.stride < elementBytes)
    fail(file, "/bufferViews/" + std::to_string(a.bufferView) + "/byteStride",
         "stride " + std::to_string(view.byteStride) + " is shorter than an element (" +
             std::to_string(elementBytes) + " bytes)");
  // The last element must end inside the view; each term is checked before it is added, so that
  // no sum can wrap around.
  const std::size_t length = view.byteLength;
  const bool fits =
      a.byteOffset <= length &&
      (a.count == 0 || (elementBytes <= length - a.byteOffset &&
                        (a.count - 1) <= (length - a.byteOffset - elementBytes) / layout.stride));
  if (!fits)
    fail(file, pointer,
         std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
             " run past the end of buffer view " + std::to_string(a.bufferView) + " (" +
             std::to_string(length) + " bytes)");
  layout.first = start + a.byteOffset;
  return layout;
}

}  // namespace

std::vector<double> readAccessor(const tinygltf::Model& model, int accessor, int components,
                                 const std::string& file) {
  const Layout layout = layoutOf(model, accessor, file);
  const std::string pointer = accessorPointer(accessor);
  if (layout.components != components)
    fail(file, pointer + "/type",
         "expected " + std::string(components == 1 ? "SCALAR" : "VEC") +
             (components == 1 ? "" : std::to_string(components)) + " elements");
  const int bytes = componentBytes(layout.componentType);
  std::vector<double> values;
  values.reserve(layout.count * components);
  for (std::size_t i = 0; i < layout.count; ++i) {
    const unsigned char* element = layout.first + i * layout.stride;
    for (int c = 0; c < components; ++c) {
      const double value = component(element + c * bytes, layout.componentType, layout.normalized);
      if (!std::isfinite(value))
        fail(file, pointer,
             "element " + std::to_string(i) + " is not a finite number (NaN or infinity)");
      values.push_back(value);
    }
  }
  return values;
}

std::vector<int> readIndices(const tinygltf::Model& model, int accessor, int vertexCount,
                             const std::string& file) {
  const Layout layout = layoutOf(model, accessor, file);
  const std::string pointer = accessorPointer(accessor);
  const bool unsignedType = layout.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                            layout.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                            layout.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (layout.components != 1 || !unsignedType || layout.normalized)
    fail(file, pointer, "indices must be SCALAR unsigned byte, short or int");
  std::vector<int> indices;
  indices.reserve(layout.count);
  for (std::size_t i = 0; i < layout.count; ++i) {
    const double index = component(layout.first + i * layout.stride, layout.componentType, false);
    if (index >= vertexCount)
      fail(file, pointer,
           "index " + std::to_string(static_cast<long long>(index)) + " (element " +
               std::to_string(i) + ") is out of range: the primitive has " +
               std::to_string(vertexCount) + " vertices");
    indices.push_back(static_cast<int>(index));
  }
  return indices;
}

std::vector<unsigned char> bufferViewBytes(const tinygltf::Model& model, int view,
                                           const std::string& file) {
  const unsigned char* start = viewStart(model, view, file, "/bufferViews/" + std::to_string(view));
  return {start, start + model.bufferViews[view].byteLength};
}

}  // namespace rad
