// RAD_CHECK and friends: a failed internal invariant throws CheckFailure, whose message names the
// bug, the check's file and line, the expression and the values compared.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "radiosity/core/check.h"

namespace rad {
namespace {

// The message of the CheckFailure that `f` throws ("" when it throws none).
template <class F>
std::string failure(F f) {
  try {
    f();
  } catch (const CheckFailure& e) {
    return e.what();
  }
  return "";
}

TEST(Check, EqMessageHasBothValuesFileAndLine) {
  const std::vector<int> radiance(3);
  const int vertices = 5;
  const int line = __LINE__ + 1;
  const std::string m = failure([&] { RAD_CHECK_EQ(radiance.size(), vertices); });
  EXPECT_NE(m.find("bug in radiosity"), std::string::npos) << m;
  EXPECT_NE(m.find("test_check.cpp:" + std::to_string(line)), std::string::npos) << m;
  EXPECT_NE(m.find("radiance.size() == vertices"), std::string::npos) << m;
  EXPECT_NE(m.find("(3 vs 5)"), std::string::npos) << m;
}

TEST(Check, PassingChecksDoNothing) {
  const size_t three = 3;
  EXPECT_NO_THROW({
    RAD_CHECK(three == 3);
    RAD_CHECK_MSG(three > 0, "never evaluated");
    RAD_CHECK_EQ(three, 3);
    RAD_CHECK_LE(three, 3);
    RAD_CHECK_LT(2, three);
    RAD_CHECK_GE(three, 3.0);
    RAD_CHECK_GT(three, -1);  // by value: -1 is not converted to a huge unsigned number
  });
}

TEST(Check, ComparisonsFail) {
  EXPECT_THROW(RAD_CHECK_LT(3, 3), CheckFailure);
  EXPECT_THROW(RAD_CHECK_LE(4, 3), CheckFailure);
  EXPECT_THROW(RAD_CHECK_GT(3, 3), CheckFailure);
  EXPECT_THROW(RAD_CHECK_GE(2.5, 3), CheckFailure);
  EXPECT_THROW(RAD_CHECK_EQ(size_t{0}, -1), CheckFailure);
  EXPECT_THROW(RAD_CHECK_LT(size_t{0}, -1), CheckFailure);
  EXPECT_THROW(RAD_CHECK(false), CheckFailure);
}

TEST(Check, OperandsAreEvaluatedOnce) {
  int calls = 0;
  auto next = [&] { return ++calls; };
  RAD_CHECK_LE(next(), 1);
  EXPECT_EQ(calls, 1);
}

TEST(Check, MessageIsAppended) {
  const std::string m =
      failure([] { RAD_CHECK_MSG(1 + 1 == 3, "arithmetic " + std::string("broke")); });
  EXPECT_NE(m.find("1 + 1 == 3"), std::string::npos) << m;
  EXPECT_NE(m.find(": arithmetic broke"), std::string::npos) << m;
}

TEST(Check, IsALogicErrorNotInputError) {
  try {
    RAD_CHECK(false);
  } catch (const std::logic_error&) {
    SUCCEED();
    return;
  }
  FAIL() << "no std::logic_error";
}

TEST(Check, DebugChecksOnlyWithoutNdebug) {
  int evaluated = 0;
  auto bump = [&] { return ++evaluated; };
#ifdef NDEBUG
  EXPECT_NO_THROW(RAD_DCHECK_EQ(bump(), 7));
  EXPECT_NO_THROW(RAD_DCHECK(bump() == 7));
  EXPECT_EQ(evaluated, 0);
#else
  EXPECT_THROW(RAD_DCHECK_EQ(bump(), 7), CheckFailure);
  EXPECT_EQ(evaluated, 1);
#endif
}

}  // namespace
}  // namespace rad
