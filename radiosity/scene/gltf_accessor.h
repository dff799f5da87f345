#pragma once

#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace rad {

// glTF accessors read with every range checked, since tinygltf leaves offsets, strides and
// counts to the caller: a bad file must be an InputError, never a read past a buffer.

// The accessor's elements as doubles, `components` per element (VEC2: 2, VEC3: 3, SCALAR: 1),
// element after element. Floats are read as they are; integer components are read as integers,
// or as [0, 1] values when the accessor is `normalized` (texture coordinates). Throws InputError
// naming `file` and the JSON pointer ("/accessors/3") for an index out of range, a wrong type,
// a sparse accessor, a view or buffer too short, or a non-finite float.
std::vector<double> readAccessor(const tinygltf::Model& model, int accessor, int components,
                                 const std::string& file);

// An index accessor (SCALAR of unsigned byte, short or int), each index checked < `vertexCount`.
std::vector<int> readIndices(const tinygltf::Model& model, int accessor, int vertexCount,
                             const std::string& file);

// The bytes a buffer view covers, checked against its buffer (an image stored in a .glb).
std::vector<unsigned char> bufferViewBytes(const tinygltf::Model& model, int view,
                                           const std::string& file);

}  // namespace rad
