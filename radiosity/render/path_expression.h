#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace rad {

// A Heckbert path expression over the vertex labels L (emitter), D (diffuse), S (specular) and
// E (eye), with `*`, `+`, `?`, `|` and parentheses; a light path is written light to eye
// ("LDSE": emitter, diffuse, specular, eye). Compiled once into a deterministic automaton, so
// matching a path's label costs one table step per vertex.
class PathExpression {
 public:
  // Throws InputError ("--paths 'EXPR': what is wrong at position N") for a malformed expression.
  static PathExpression parse(const std::string& text);

  // True when the whole label (a string over L, D, S, E) belongs to the expression's language.
  bool matches(std::string_view label) const;
  const std::string& text() const { return text_; }

 private:
  static constexpr int kSymbols = 4;  // L, D, S, E
  std::string text_;
  std::vector<std::array<int, kSymbols>> next_;  // DFA transitions, -1: dead
  std::vector<char> accepting_;
};

}  // namespace rad
