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

// Reads and parses `path` (a `what` file, for the message when it cannot be opened); a missing
// file, malformed JSON (with its line) or an unreadable value (e.g. a number that overflows a
// double) is an InputError naming the file.
JsonFile readJsonFile(const std::string& path, const std::string& what = "camera");

// The 1-based line holding byte `byte` of `text`: nlohmann reports byte offsets, people want lines.
int lineOfByte(const std::string& text, size_t byte);

// The 1-based line where the value at JSON pointer `pointer` (RFC 6901, e.g. "/lights/2/type")
// starts in `text`, which must hold valid JSON; 0 when the pointer names no value (or a key with
// escapes). Scans without recursion, so deeply nested input costs no stack.
int lineOfPointer(const std::string& text, const std::string& pointer);

// `<scene without its extension><suffix>`: a sidecar file that ships next to a scene.
std::string sidecarPath(const std::string& scenePath, const std::string& suffix);

}  // namespace rad
