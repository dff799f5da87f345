#pragma once

#include <string>
#include <vector>

namespace rad {

// One `map_Kd`, `map_Ke` or `map_d` statement of an MTL library: the image it names, resolved
// against the library's folder, and where it was written (for errors about the image).
struct TextureMapStatement {
  std::string path;  // empty: the material has no such map
  std::string file;  // the MTL library
  int line = 0;
  bool present() const { return !path.empty(); }
};

// Reads the tokens of a `map_*` statement (keyword first): options, then the file name (the rest
// of the line, so names with spaces work; Windows backslashes are read as folder separators).
// Options that change only bump or reflection maps (-bm, -boost, -mm, -texres, -blendu/-blendv,
// -cc, -type) are skipped; -s, -o, -t other than their identity values, -clamp on and -imfchan
// are not supported and are skipped with a warning naming the line, since the texture then maps
// differently from what the file asks. A malformed option or a missing file name is an
// InputError at the line.
TextureMapStatement parseTextureMap(const std::vector<std::string>& tokens,
                                    const std::string& mtlFile, int line);

}  // namespace rad
