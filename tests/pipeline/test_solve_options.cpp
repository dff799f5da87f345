// Options that do nothing with the chosen method are errors that name the option and say why;
// options that apply pass.
#include <gtest/gtest.h>

#include "radiosity/core/errors.h"
#include "radiosity/pipeline/solve_options.h"

namespace rad {
namespace {

// The message checkOptionsApply gives, or "" when it accepts.
std::string refusal(const SolveOptions& options, const std::set<std::string>& given) {
  try {
    checkOptionsApply(options, given);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

SolveOptions analytic() {
  SolveOptions o;
  o.formFactors = FormFactorMethod::Analytic;
  return o;
}

TEST(OptionsApply, RaysWithAnalyticFactorsIsRefusedNamingTheOption) {
  const std::string message = refusal(analytic(), {"--rays", "--seed"});
  EXPECT_EQ(message.rfind("--rays is not used", 0), 0u) << message;
  EXPECT_NE(message.find("--shadow-rays"), std::string::npos) << message;
  EXPECT_EQ(refusal(SolveOptions(), {"--rays", "--seed"}), "");
}

TEST(OptionsApply, AnalyticOnlyOptionsWithHemisphereRowsAreRefused) {
  for (const char* name : {"--patch-area", "--shadow-rays", "--receiver-points"}) {
    EXPECT_EQ(refusal(SolveOptions(), {name}).rfind(std::string(name) + " is not used", 0), 0u)
        << name;
    EXPECT_EQ(refusal(analytic(), {name}), "") << name;
  }
}

TEST(OptionsApply, RefinementOptionsNeedARefineThreshold) {
  SolveOptions refining = analytic();
  refining.refineThreshold = 0.1;
  for (const char* name : {"--min-area", "--max-elements", "--refine-passes"}) {
    EXPECT_NE(refusal(analytic(), {name}).find("--refine-threshold"), std::string::npos) << name;
    EXPECT_EQ(refusal(refining, {name}), "") << name;
  }
}

TEST(OptionsApply, ElementsWithMaxAreaAndToleranceWithBouncesAreRefused) {
  SolveOptions o;
  o.maxArea = 0.01;
  EXPECT_NE(refusal(o, {"--elements", "--max-area"}).find("--elements is not used"),
            std::string::npos);
  EXPECT_EQ(refusal(SolveOptions(), {"--elements"}), "");
  EXPECT_NE(refusal(o, {"--element-size", "--max-area"}).find("--element-size is not used"),
            std::string::npos);
  SolveOptions sized;
  sized.elementSize = 0.2;
  EXPECT_NE(refusal(sized, {"--elements", "--element-size"}).find("--elements is not used"),
            std::string::npos);
  EXPECT_EQ(refusal(sized, {"--element-size"}), "");
  SolveOptions bounces;
  bounces.solver = SolverKind::Jacobi;
  bounces.bounces = 3;
  EXPECT_NE(refusal(bounces, {"--tolerance", "--bounces"}).find("--tolerance is not used"),
            std::string::npos);
}

TEST(OptionsValues, OutOfRangeValuesAreRefused) {
  SolveOptions o;
  o.raysPerElement = 0;
  EXPECT_THROW(validateSolveOptions(o), InputError);
  o = SolveOptions();
  o.tolerance = std::nan("");
  EXPECT_THROW(validateSolveOptions(o), InputError);
  o = SolveOptions();
  o.bounces = 2;  // with the progressive solver
  EXPECT_THROW(validateSolveOptions(o), InputError);
  EXPECT_NO_THROW(validateSolveOptions(SolveOptions()));
}

}  // namespace
}  // namespace rad
