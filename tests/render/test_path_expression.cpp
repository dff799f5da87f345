// Heckbert path expressions: the languages of the classic examples, and clear errors.
#include <gtest/gtest.h>

#include "radiosity/core/errors.h"
#include "radiosity/render/path_binning.h"
#include "radiosity/render/path_expression.h"

namespace rad {
namespace {

bool matches(const std::string& expression, const std::string& label) {
  return PathExpression::parse(expression).matches(label);
}

TEST(PathExpression, LiteralsMatchExactlyTheirOwnLabel) {
  EXPECT_TRUE(matches("LDE", "LDE"));
  EXPECT_FALSE(matches("LDE", "LDDE"));
  EXPECT_FALSE(matches("LDE", "LD"));
  EXPECT_FALSE(matches("LDE", "LSE"));
  EXPECT_TRUE(matches("LE", "LE"));
  EXPECT_FALSE(matches("LE", "LDE"));
}

TEST(PathExpression, RepetitionOperators) {
  EXPECT_TRUE(matches("LD*E", "LE"));
  EXPECT_TRUE(matches("LD*E", "LDDDE"));
  EXPECT_FALSE(matches("LD+E", "LE"));
  EXPECT_TRUE(matches("LD+E", "LDDE"));
  EXPECT_TRUE(matches("LD?E", "LE"));
  EXPECT_TRUE(matches("LD?E", "LDE"));
  EXPECT_FALSE(matches("LD?E", "LDDE"));
  EXPECT_TRUE(matches("LS+DE", "LSSDE"));
  EXPECT_FALSE(matches("LS+DE", "LDE"));
  EXPECT_FALSE(matches("LS+DE", "LSDDE"));
}

TEST(PathExpression, AlternationAndGroups) {
  EXPECT_TRUE(matches("L(D|S)*E", "LDSSDE"));
  EXPECT_FALSE(matches("L(D|S)*E", "LDLE"));
  EXPECT_TRUE(matches("LD?S*E", "LSSE"));  // Whitted's paths
  EXPECT_TRUE(matches("LD?S*E", "LDSE"));
  EXPECT_FALSE(matches("LD?S*E", "LSDE"));
  EXPECT_TRUE(matches("LE|LDE", "LDE"));
  EXPECT_TRUE(matches("(LD)+E", "LDLDE"));
  EXPECT_TRUE(matches("L ( D | S ) + E", "LSDE"));  // spaces are ignored
  EXPECT_TRUE(matches("LD**E", "LDDE"));            // a repeated repetition is still one
}

// The four expressions of the partition test cover every L(D|S)*E label exactly once.
TEST(PathExpression, PartitionCoversEveryLabelOnce) {
  const std::vector<PathExpression> parts = {
      PathExpression::parse("LE"), PathExpression::parse("LDE"), PathExpression::parse("LD(D|S)+E"),
      PathExpression::parse("LS(D|S)*E")};
  const std::string symbols = "DS";
  for (int length = 0; length <= 6; ++length)
    for (int code = 0; code < (1 << length); ++code) {
      std::string label = "L";
      for (int i = 0; i < length; ++i) label.push_back(symbols[(code >> i) & 1]);
      label.push_back('E');
      int count = 0;
      for (const PathExpression& p : parts) count += p.matches(label);
      EXPECT_EQ(count, 1) << label;
    }
}

TEST(PathExpression, BounceBinningCountsScatteringVertices) {
  const BounceBinning bins(2);
  EXPECT_EQ(bins.binCount(), 3);
  EXPECT_EQ(bins.binOf("LE"), 0);
  EXPECT_EQ(bins.binOf("LSE"), 1);
  EXPECT_EQ(bins.binOf("LDSE"), 2);
  EXPECT_EQ(bins.binOf("LDSDE"), -1);
}

void expectError(const std::string& expression, const std::string& fragment) {
  try {
    PathExpression::parse(expression);
    ADD_FAILURE() << "no error for '" << expression << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--paths '" + expression + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(PathExpression, MalformedExpressionsAreClearErrors) {
  expectError("", "empty");
  expectError("LX", "unknown symbol 'X' at position 2");
  expectError("ld", "unknown symbol 'l' at position 1");
  expectError("L(DE", "missing ')'");
  expectError("LD)E", "unmatched ')' at position 3");
  expectError("*LE", "nothing to repeat");
  expectError("L|", "ends where a symbol");
  expectError("L||E", "'|' with nothing before it");
  expectError("L()E", "')' with nothing before it");
}

}  // namespace
}  // namespace rad
