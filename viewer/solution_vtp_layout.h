#pragma once

#include <string>
#include <string_view>

namespace rad {

// Checks, before VTK's XML reader sees them, that the bytes of a solution.vtp have exactly the
// layout writeSolutionVtp produces: one PolyData piece of triangles, every array "appended" as
// raw zlib-compressed blocks (UInt32 headers), laid end to end in document order, each holding
// exactly NumberOfTuples × NumberOfComponents values (tuples: the points, the cells, or the field
// array's NumberOfTuples), the only String array a field array, triangles' offsets 3, 6, 9, ...
// VTK 9.1's reader trusts the counts in the file (a String array with more strings than
// NumberOfTuples makes it write past its array), so the viewer only hands it files that pass.
// Throws InputError naming the file and the line of the offending element.
void checkSolutionVtpLayout(const std::string& path, std::string_view bytes);

}  // namespace rad
