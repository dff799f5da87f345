#include "radiosity/scene/json_file.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "radiosity/core/errors.h"

namespace rad {

int lineOfByte(const std::string& text, size_t byte) {
  int line = 1;
  for (size_t i = 0; i < std::min(byte, text.size()); ++i) line += text[i] == '\n';
  return line;
}

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

size_t skipSpace(const std::string& t, size_t i) {
  while (i < t.size() && isSpace(t[i])) ++i;
  return i;
}

// `i` at an opening quote: the index just past the closing one.
size_t skipString(const std::string& t, size_t i) {
  for (++i; i < t.size() && t[i] != '"'; ++i)
    if (t[i] == '\\') ++i;
  return std::min(t.size(), i + 1);
}

// `i` at the start of a value: the index just past it.
size_t skipValue(const std::string& t, size_t i) {
  if (i >= t.size()) return i;
  if (t[i] == '"') return skipString(t, i);
  if (t[i] != '{' && t[i] != '[') {
    while (i < t.size() && !isSpace(t[i]) && t[i] != ',' && t[i] != ']' && t[i] != '}') ++i;
    return i;
  }
  int depth = 0;
  while (i < t.size()) {
    const char c = t[i];
    if (c == '"') {
      i = skipString(t, i);
      continue;
    }
    depth += (c == '{' || c == '[') - (c == '}' || c == ']');
    ++i;
    if (depth == 0) break;
  }
  return i;
}

// The start of the member `key` (or element `key` of an array) of the container at `i`, or npos.
size_t findChild(const std::string& t, size_t i, const std::string& key) {
  if (i >= t.size() || (t[i] != '{' && t[i] != '[')) return std::string::npos;
  const bool object = t[i] == '{';
  long index = -1;
  if (!object) {
    if (key.empty() || key.size() > 9 || key.find_first_not_of("0123456789") != std::string::npos)
      return std::string::npos;
    index = std::stol(key);
  }
  i = skipSpace(t, i + 1);
  for (long k = 0; i < t.size() && t[i] != '}' && t[i] != ']'; ++k) {
    bool match = k == index;
    if (object) {
      const size_t end = skipString(t, i);
      match = end >= i + 2 && t.compare(i + 1, end - i - 2, key) == 0;
      i = skipSpace(t, end);
      if (i >= t.size() || t[i] != ':') return std::string::npos;
      i = skipSpace(t, i + 1);
    }
    if (match) return i;
    i = skipSpace(t, skipValue(t, i));
    if (i < t.size() && t[i] == ',') i = skipSpace(t, i + 1);
  }
  return std::string::npos;
}

}  // namespace

int lineOfPointer(const std::string& text, const std::string& pointer) {
  size_t at = skipSpace(text, 0);
  size_t from = 0;
  while (from < pointer.size() && at != std::string::npos) {
    if (pointer[from] != '/') return 0;
    const size_t next = std::min(pointer.find('/', from + 1), pointer.size());
    std::string token = pointer.substr(from + 1, next - from - 1);
    for (size_t p = 0; (p = token.find('~', p)) != std::string::npos; ++p)
      token.replace(p, 2, p + 1 < token.size() && token[p + 1] == '1' ? "/" : "~");
    at = findChild(text, at, token);
    from = next;
  }
  return at == std::string::npos ? 0 : lineOfByte(text, at);
}

std::string sidecarPath(const std::string& scenePath, const std::string& suffix) {
  std::string base = scenePath;
  const size_t slash = base.find_last_of('/');
  const size_t dot = base.find_last_of('.');
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) base.resize(dot);
  return base + suffix;
}

JsonFile readJsonFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open " + what + " file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  JsonFile file;
  file.text = buffer.str();
  try {
    file.value = nlohmann::json::parse(file.text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path, lineOfByte(file.text, e.byte),
                     "malformed JSON: " + std::string(e.what()));
  } catch (const nlohmann::json::exception& e) {  // e.g. a number that overflows a double
    throw InputError(path, 0, "unreadable JSON: " + std::string(e.what()));
  }
  return file;
}

}  // namespace rad
