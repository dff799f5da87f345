#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace rad {

// A JSON sidecar read whole: its text (to turn positions into line numbers for errors) and the
// parsed value.
struct JsonFile {
  std::string text;
  nlohmann::json value;
};

// Reads and parses `path`; a missing file, malformed JSON (with its line) or an unreadable value
// (e.g. a number that overflows a double) is an InputError naming the file.
JsonFile readJsonFile(const std::string& path);

// The 1-based line holding byte `byte` of `text`: nlohmann reports byte offsets, people want lines.
int lineOfByte(const std::string& text, size_t byte);

}  // namespace rad
