#include "radiosity/render/path_expression.h"

#include <map>
#include <set>

#include "radiosity/core/errors.h"

namespace rad {
namespace {

int symbolIndex(char c) {
  switch (c) {
    case 'L':
      return 0;
    case 'D':
      return 1;
    case 'S':
      return 2;
    case 'E':
      return 3;
    default:
      return -1;
  }
}

// Thompson's construction: each state has at most one symbol edge and any number of ε edges.
struct Nfa {
  struct State {
    int symbol = -1, target = -1;  // symbol edge (symbol index), if any
    std::vector<int> epsilon;
  };
  std::vector<State> states;
  int add() {
    states.emplace_back();
    return static_cast<int>(states.size()) - 1;
  }
};

struct Fragment {
  int start, accept;
};

// Recursive descent over  alternation := sequence ('|' sequence)*,  sequence := repeat+,
// repeat := atom ('*' | '+' | '?')*,  atom := L | D | S | E | '(' alternation ')'.
class Parser {
 public:
  Parser(const std::string& text, Nfa& nfa) : text_(text), nfa_(nfa) {}

  Fragment parseAll() {
    skipSpaces();
    if (pos_ == text_.size()) fail("the expression is empty");
    const Fragment f = alternation();
    if (pos_ < text_.size())
      fail(text_[pos_] == ')' ? "unmatched ')'"
                              : "unexpected '" + std::string(1, text_[pos_]) + "'");
    return f;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("--paths '" + text_ + "': " + what + " at position " +
                     std::to_string(pos_ + 1) +
                     " (expected a Heckbert expression over L, D, S, E with * + ? | and "
                     "parentheses, e.g. LS+DE)");
  }
  void skipSpaces() {
    while (pos_ < text_.size() && text_[pos_] == ' ') ++pos_;
  }
  bool peek(char c) {
    skipSpaces();
    return pos_ < text_.size() && text_[pos_] == c;
  }

  Fragment alternation() {
    Fragment f = sequence();
    while (peek('|')) {
      ++pos_;
      const Fragment g = sequence();
      const int s = nfa_.add(), a = nfa_.add();
      nfa_.states[s].epsilon = {f.start, g.start};
      nfa_.states[f.accept].epsilon.push_back(a);
      nfa_.states[g.accept].epsilon.push_back(a);
      f = {s, a};
    }
    return f;
  }

  Fragment sequence() {
    skipSpaces();
    if (pos_ == text_.size() || text_[pos_] == '|' || text_[pos_] == ')')
      fail(pos_ == text_.size() ? "the expression ends where a symbol or '(' is needed"
                                : "'" + std::string(1, text_[pos_]) + "' with nothing before it");
    Fragment f = repeat();
    for (;;) {
      skipSpaces();
      if (pos_ == text_.size() || text_[pos_] == '|' || text_[pos_] == ')') return f;
      const Fragment g = repeat();
      nfa_.states[f.accept].epsilon.push_back(g.start);
      f.accept = g.accept;
    }
  }

  Fragment repeat() {
    Fragment f = atom();
    while (peek('*') || peek('+') || peek('?')) {
      const char op = text_[pos_++];
      const int s = nfa_.add(), a = nfa_.add();
      nfa_.states[s].epsilon.push_back(f.start);
      nfa_.states[f.accept].epsilon.push_back(a);
      if (op != '+') nfa_.states[s].epsilon.push_back(a);               // zero times
      if (op != '?') nfa_.states[f.accept].epsilon.push_back(f.start);  // again
      f = {s, a};
    }
    return f;
  }

  Fragment atom() {
    skipSpaces();
    const char c = text_[pos_];
    if (c == '(') {
      ++pos_;
      const Fragment f = alternation();
      if (!peek(')')) fail("missing ')'");
      ++pos_;
      return f;
    }
    const int symbol = symbolIndex(c);
    if (symbol < 0) {
      if (c == '*' || c == '+' || c == '?')
        fail("'" + std::string(1, c) + "' with nothing to repeat");
      fail("unknown symbol '" + std::string(1, c) + "'");
    }
    ++pos_;
    const int s = nfa_.add(), a = nfa_.add();
    nfa_.states[s].symbol = symbol;
    nfa_.states[s].target = a;
    return {s, a};
  }

  const std::string& text_;
  Nfa& nfa_;
  size_t pos_ = 0;
};

std::set<int> closure(const Nfa& nfa, std::set<int> states) {
  std::vector<int> stack(states.begin(), states.end());
  while (!stack.empty()) {
    const int s = stack.back();
    stack.pop_back();
    for (int t : nfa.states[s].epsilon)
      if (states.insert(t).second) stack.push_back(t);
  }
  return states;
}

}  // namespace

PathExpression PathExpression::parse(const std::string& text) {
  Nfa nfa;
  const Fragment f = Parser(text, nfa).parseAll();
  // Subset construction: the automaton has few states for any expression a user writes.
  PathExpression e;
  e.text_ = text;
  std::map<std::set<int>, int> ids;
  std::vector<std::set<int>> sets{closure(nfa, {f.start})};
  ids[sets[0]] = 0;
  for (size_t i = 0; i < sets.size(); ++i) {
    std::array<int, kSymbols> row;
    for (int symbol = 0; symbol < kSymbols; ++symbol) {
      std::set<int> moved;
      for (int s : sets[i])
        if (nfa.states[s].symbol == symbol) moved.insert(nfa.states[s].target);
      if (moved.empty()) {
        row[symbol] = -1;
        continue;
      }
      const std::set<int> target = closure(nfa, std::move(moved));
      auto [it, added] = ids.emplace(target, static_cast<int>(sets.size()));
      if (added) sets.push_back(target);
      row[symbol] = it->second;
    }
    e.next_.push_back(row);
    e.accepting_.push_back(sets[i].count(f.accept) > 0);
  }
  return e;
}

bool PathExpression::matches(std::string_view label) const {
  int state = 0;
  for (char c : label) {
    const int symbol = symbolIndex(c);
    if (symbol < 0) return false;
    state = next_[state][symbol];
    if (state < 0) return false;
  }
  return accepting_[state] != 0;
}

}  // namespace rad
