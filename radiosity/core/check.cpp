#include "radiosity/core/check.h"

namespace rad::check_detail {

void fail(const char* file, int line, const char* expression, const std::string& values,
          const std::string& message) {
  std::string what = "bug in radiosity: " + std::string(file) + ":" + std::to_string(line) +
                     ": check failed: " + expression;
  if (!values.empty()) what += " (" + values + ")";
  if (!message.empty()) what += ": " + message;
  throw CheckFailure(what);
}

}  // namespace rad::check_detail
