#pragma once

#include <string>
#include <vector>

#include "radiosity/scene/mtl_line_check.h"

namespace rad {

// What the line-level pass over an OBJ file and its MTL libraries found. tinyobjloader reports
// neither line numbers nor most errors, so this pass validates everything first and then hands
// tinyobjloader exactly the text it checked.
struct ObjLineCheck {
  // The OBJ for tinyobjloader, line for line: comments removed, whitespace normalised, statements
  // the loader does not need blanked, and only the first `mtllib` kept, because mtlText below
  // already holds every library and tinyobjloader reads it all at that first `mtllib`.
  std::string objText;
  // Every MTL library the OBJ names, checked and concatenated in the order they were first named.
  std::string mtlText;
  std::vector<MaterialSource> materials;  // index = tinyobjloader's material id
  std::vector<int> faceLines;             // line of each `f`, in file order
  std::vector<int> faceSizes;             // vertex count of each `f`, in file order
  std::vector<int> vertexLines;           // line of each `v`, in file order
  long vertexCount = 0;
  long texcoordCount = 0;
};

// Scans `objPath` and each MTL library its `mtllib` lines name (relative to the OBJ's directory).
// Throws InputError "file:line: message" for: a file that cannot be opened (an MTL one at the
// `mtllib` line), malformed or non-finite numbers and too few components on `v` lines, face (and
// line/point) indices that are not integers, zero or out of range, faces with fewer than 3
// vertices, `vt` lines without 1 to 3 finite numbers, `usemtl` of a material no library loaded so
// far defines, and any MTL error that checkMtlText() reports.
ObjLineCheck checkObjFile(const std::string& objPath);

}  // namespace rad
