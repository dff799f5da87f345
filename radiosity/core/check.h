#pragma once

// Internal invariants: conditions that only a bug in radiosity can break (arrays the program
// built itself out of step, an API called against its contract). Bad input from a user's scene or
// options is an InputError instead (errors.h), found and reported before it reaches such code.
//
//   RAD_CHECK(cond)                 RAD_CHECK_MSG(cond, "why it must hold")
//   RAD_CHECK_EQ(a, b)  RAD_CHECK_LE(a, b)  RAD_CHECK_LT(a, b)  (also _GE, _GT): print a and b
//   RAD_DCHECK...                   the same, only where NDEBUG is not defined (debug builds);
//                                   otherwise nothing is evaluated, but the code still compiles.
//
// A failed check throws CheckFailure; the command line reports it as an internal error (exit 3).
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace rad {

class CheckFailure : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

namespace check_detail {

// "bug in radiosity: FILE:LINE: check failed: EXPR (VALUES): MESSAGE".
[[noreturn]] void fail(const char* file, int line, const char* expression,
                       const std::string& values, const std::string& message);

template <class T, class = void>
struct Printable : std::false_type {};
template <class T>
struct Printable<T,
                 std::void_t<decltype(std::declval<std::ostream&>() << std::declval<const T&>())>>
    : std::true_type {};

template <class A, class B>
std::string values(const A& a, const B& b) {
  std::ostringstream s;
  s.precision(17);
  auto print = [&s](const auto& v) {
    if constexpr (Printable<std::decay_t<decltype(v)>>::value)
      s << v;
    else
      s << "(unprintable)";
  };
  print(a);
  s << " vs ";
  print(b);
  return s.str();
}

// Integers of different signedness compare by value (-1 < 0u), without -Wsign-compare.
template <class T>
constexpr bool kInteger = std::is_integral_v<T> && !std::is_same_v<T, bool>;
template <class A, class B>
constexpr bool mixedSign() {
  if constexpr (kInteger<A> && kInteger<B>) return std::is_signed_v<A> != std::is_signed_v<B>;
  return false;
}

// In the mixed case both are non-negative once the sign is tested: compare them widened.
template <class T>
unsigned long long widened(T v) {
  return static_cast<unsigned long long>(v);
}
template <class T>
bool negative(T v) {
  if constexpr (std::is_signed_v<T>)
    return v < 0;
  else
    return false;
}

template <class A, class B>
bool equal(const A& a, const B& b) {
  if constexpr (mixedSign<A, B>())
    return !negative(a) && !negative(b) && widened(a) == widened(b);
  else
    return a == b;
}
template <class A, class B>
bool less(const A& a, const B& b) {
  if constexpr (mixedSign<A, B>())
    return negative(a) || (!negative(b) && widened(a) < widened(b));
  else
    return a < b;
}
template <class A, class B>
bool lessEqual(const A& a, const B& b) {
  if constexpr (mixedSign<A, B>())
    return !less(b, a);
  else
    return a <= b;
}

}  // namespace check_detail
}  // namespace rad

#define RAD_CHECK_MSG(cond, message)                                                  \
  do {                                                                                \
    if (!(cond)) ::rad::check_detail::fail(__FILE__, __LINE__, #cond, {}, (message)); \
  } while (false)
#define RAD_CHECK(cond) RAD_CHECK_MSG(cond, std::string())

// `test` compares rad_check_a_ and rad_check_b_, which hold a and b (each evaluated once).
#define RAD_CHECK_COMPARE_(test, a, b, text)                                                  \
  do {                                                                                        \
    const auto& rad_check_a_ = (a);                                                           \
    const auto& rad_check_b_ = (b);                                                           \
    if (!(test))                                                                              \
      ::rad::check_detail::fail(__FILE__, __LINE__, text,                                     \
                                ::rad::check_detail::values(rad_check_a_, rad_check_b_), {}); \
  } while (false)
#define RAD_CHECK_EQ(a, b) \
  RAD_CHECK_COMPARE_(::rad::check_detail::equal(rad_check_a_, rad_check_b_), a, b, #a " == " #b)
#define RAD_CHECK_LT(a, b) \
  RAD_CHECK_COMPARE_(::rad::check_detail::less(rad_check_a_, rad_check_b_), a, b, #a " < " #b)
#define RAD_CHECK_LE(a, b) \
  RAD_CHECK_COMPARE_(::rad::check_detail::lessEqual(rad_check_a_, rad_check_b_), a, b, #a " <= " #b)
#define RAD_CHECK_GT(a, b) \
  RAD_CHECK_COMPARE_(::rad::check_detail::less(rad_check_b_, rad_check_a_), a, b, #a " > " #b)
#define RAD_CHECK_GE(a, b) \
  RAD_CHECK_COMPARE_(::rad::check_detail::lessEqual(rad_check_b_, rad_check_a_), a, b, #a " >= " #b)

// Debug-only checks: `if (false)` keeps the expression compiled (names, types) but never run.
#ifdef NDEBUG
#define RAD_DCHECK_OFF_(check) \
  do {                         \
    if (false) check;          \
  } while (false)
#else
#define RAD_DCHECK_OFF_(check) check
#endif
#define RAD_DCHECK(cond) RAD_DCHECK_OFF_(RAD_CHECK(cond))
#define RAD_DCHECK_MSG(cond, message) RAD_DCHECK_OFF_(RAD_CHECK_MSG(cond, message))
#define RAD_DCHECK_EQ(a, b) RAD_DCHECK_OFF_(RAD_CHECK_EQ(a, b))
#define RAD_DCHECK_LT(a, b) RAD_DCHECK_OFF_(RAD_CHECK_LT(a, b))
#define RAD_DCHECK_LE(a, b) RAD_DCHECK_OFF_(RAD_CHECK_LE(a, b))
#define RAD_DCHECK_GT(a, b) RAD_DCHECK_OFF_(RAD_CHECK_GT(a, b))
#define RAD_DCHECK_GE(a, b) RAD_DCHECK_OFF_(RAD_CHECK_GE(a, b))
