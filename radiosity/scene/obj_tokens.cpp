#include "radiosity/scene/obj_tokens.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

// The largest decimal exponent of a finite double (DBL_MAX_10_EXP).
constexpr int kMaxDecimalExponent = 308;

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }

void tokenizeLine(const char* begin, const char* end, std::vector<std::string>* tokens) {
  tokens->clear();
  for (const char* c = begin; c != end; ++c) {
    if (*c == '#') {
      end = c;
      break;
    }
  }
  const char* c = begin;
  while (c != end) {
    while (c != end && isBlank(*c)) ++c;
    const char* start = c;
    while (c != end && !isBlank(*c)) ++c;
    if (c != start) tokens->emplace_back(start, c);
  }
}

std::string quoted(const std::string& token) { return "'" + token + "'"; }

}  // namespace

void forEachLine(const std::string& text, const LineVisitor& visit) {
  std::vector<std::string> tokens;
  const char* c = text.data();
  const char* const end = c + text.size();
  int line = 0;
  while (c != end) {
    const char* stop = c;
    while (stop != end && *stop != '\n' && *stop != '\r') ++stop;
    tokenizeLine(c, stop, &tokens);
    visit(++line, tokens);
    if (stop != end && *stop == '\r' && stop + 1 != end && stop[1] == '\n') ++stop;
    c = stop == end ? end : stop + 1;
  }
}

bool readTextFile(const std::string& path, std::string* text) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return false;  // opens on Linux, then reads nothing
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) return false;
  *text = buffer.str();
  // A UTF-8 byte-order mark would otherwise glue itself to the first keyword.
  if (text->compare(0, 3, "\xEF\xBB\xBF") == 0) text->erase(0, 3);
  return true;
}

std::string joinTokens(const std::vector<std::string>& tokens) {
  std::string line;
  for (const std::string& token : tokens) {
    if (!line.empty()) line += ' ';
    line += token;
  }
  return line;
}

double parseNumberToken(const std::string& token, const std::string& keyword,
                        const std::string& file, int line) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  const bool whole = end == begin + token.size() && !token.empty();
  if (whole && !std::isfinite(value)) {
    throw InputError(file, line,
                     "non-finite number " + quoted(token) + " in '" + keyword +
                         "' statement (NaN and infinity are not allowed)");
  }
  // Only decimal notation: strtod also takes hex ("0x1p3"), which tinyobjloader reads as 0.
  const bool decimal = token.find_first_not_of("+-.0123456789eE") == std::string::npos;
  if (!whole || !decimal) {
    throw InputError(file, line,
                     "malformed number " + quoted(token) + " in '" + keyword + "' statement");
  }
  // tinyobjloader multiplies the mantissa by pow(10, exponent): beyond ±308 that power is
  // infinite or zero, and "0e400" (0 here) becomes 0 × inf = NaN there.
  const std::size_t e = token.find_first_of("eE");
  if (e != std::string::npos) {
    std::string digits = token.substr(e + 1 + (token[e + 1] == '+' || token[e + 1] == '-'));
    digits.erase(0, std::min(digits.size(), digits.find_first_not_of('0')));
    if (digits.size() > 3 || (!digits.empty() && std::stoi(digits) > kMaxDecimalExponent)) {
      throw InputError(file, line,
                       "number " + quoted(token) + " in '" + keyword +
                           "' statement has an exponent beyond ±" +
                           std::to_string(kMaxDecimalExponent));
    }
  }
  return value;
}

std::vector<double> parseNumbers(const std::vector<std::string>& tokens, std::size_t minCount,
                                 std::size_t maxCount, const std::string& file, int line) {
  const std::string& keyword = tokens.front();
  const std::size_t found = tokens.size() - 1;
  if (found < minCount || found > maxCount) {
    std::string expected = minCount == maxCount ? "exactly " + std::to_string(minCount)
                           : found < minCount   ? "at least " + std::to_string(minCount)
                                                : "at most " + std::to_string(maxCount);
    throw InputError(file, line,
                     "'" + keyword + "' needs " + expected + " number" +
                         (minCount == 1 && maxCount == 1 ? "" : "s") + ", found " +
                         std::to_string(found));
  }
  std::vector<double> values;
  values.reserve(found);
  for (std::size_t i = 1; i < tokens.size(); ++i) {
    values.push_back(parseNumberToken(tokens[i], keyword, file, line));
  }
  return values;
}

bool parseIntegerToken(const std::string& token, long* value) {
  if (token.empty()) return false;
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  const long parsed = std::strtol(begin, &end, 10);
  if (end != begin + token.size() || errno == ERANGE) return false;
  // strtol skips leading spaces and accepts a lone sign; neither can appear in a token here,
  // but a sign with no digits must still be refused.
  if (token.find_first_of("0123456789") == std::string::npos) return false;
  if (parsed < INT_MIN || parsed > INT_MAX) return false;
  *value = parsed;
  return true;
}

}  // namespace rad
