#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rad {

// Shared lexical rules of the OBJ and MTL line checks, strict enough that what passes them is read
// the same way by tinyobjloader.

// Calls visit(line, tokens) for every line of `text`, numbered from 1, with the line's
// whitespace-separated tokens and `#` comments removed (tokens may be empty). Lines may end in
// \n, \r\n or \r, as tinyobjloader's own line splitting accepts all three. Streams: large files
// are never held as tokens all at once.
using LineVisitor = std::function<void(int line, const std::vector<std::string>& tokens)>;
void forEachLine(const std::string& text, const LineVisitor& visit);

// Reads a whole file into `text`, without a leading UTF-8 byte-order mark; false when it cannot
// be opened or read.
bool readTextFile(const std::string& path, std::string* text);

// Joins tokens with single spaces: the normalised line handed on to tinyobjloader.
std::string joinTokens(const std::vector<std::string>& tokens);

// The whole token must be a finite decimal number with an exponent within ±308. Hex, nan/inf
// and larger exponents are refused because strtod accepts them but tinyobjloader's own number
// parser does not read them the same way ("0e400": 0 for strtod, NaN for tinyobjloader).
// Throws InputError(file, line, ...) naming the token and the statement's keyword.
double parseNumberToken(const std::string& token, const std::string& keyword,
                        const std::string& file, int line);

// Reads tokens[1..] of a statement as numbers, between minCount and maxCount of them.
std::vector<double> parseNumbers(const std::vector<std::string>& tokens, std::size_t minCount,
                                 std::size_t maxCount, const std::string& file, int line);

// The whole token must be an integer (optional sign) that fits an int.
bool parseIntegerToken(const std::string& token, long* value);

}  // namespace rad
