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

JsonFile readJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open camera file");
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
