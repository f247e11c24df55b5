// The command-line calculator entry point.

#include "expr/standalone.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace openmss::expr {
namespace {

TEST(Standalone, EvaluatesValueAndTimeDerivative) {
  Diagnostics diags;
  double value = 0.0;
  double rate = 0.0;
  ASSERT_TRUE(evaluateStandalone("POLY(TIME, 0, 0, 360D)", 0.25, &value, &rate, diags));
  EXPECT_NEAR(value, std::numbers::pi / 2.0, 1e-15);
  EXPECT_NEAR(rate, 2.0 * std::numbers::pi, 1e-15);
  EXPECT_FALSE(diags.hasErrors());
  ASSERT_TRUE(evaluateStandalone("2**3**2", 0.0, &value, nullptr, diags));
  EXPECT_DOUBLE_EQ(value, 512.0);
}

TEST(Standalone, RefusesExpressionsThatNeedAModel) {
  Diagnostics diags;
  double value = -1.0;
  EXPECT_FALSE(evaluateStandalone("1 + DM(1,2)", 0.0, &value, nullptr, diags));
  EXPECT_DOUBLE_EQ(value, -1.0);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "<command line>: error: DM at column 5 of the expression needs a model, and the "
            "calculator evaluates expressions without one. Use numbers, constants, TIME and "
            "functions such as STEP or POLY.");
}

TEST(Standalone, RefusesSplineFunctionsWithoutAModel) {
  Diagnostics diags;
  EXPECT_FALSE(evaluateStandalone("AKISPL(0.5, 0, 1)", 0.0, nullptr, nullptr, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "<command line>: error: AKISPL at column 1 of the expression needs a model, and the "
            "calculator evaluates expressions without one. Use numbers, constants, TIME and "
            "functions such as STEP or POLY.");
}

TEST(Standalone, RefusesUserAndEvaluatesVectors) {
  Diagnostics diags;
  EXPECT_FALSE(evaluateStandalone("USER(1, 2)", 0.0, nullptr, nullptr, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "<command line>: error: USER at column 1 of the expression needs a user subroutine, "
            "and the calculator loads none. Use numbers, constants, TIME and functions such as "
            "STEP or POLY.");
  double value = 0.0, rate = 0.0;
  Diagnostics ok;
  ASSERT_TRUE(evaluateStandalone("MAG([3*TIME, 4, 12])", 1.0, &value, &rate, ok));
  EXPECT_DOUBLE_EQ(value, 13.0);
  EXPECT_NEAR(rate, 9.0 / 13.0, 1e-15);  // d/dt sqrt(9t^2 + 160) = 9t / |v|
}

TEST(Standalone, ReportsSyntaxErrors) {
  Diagnostics diags;
  EXPECT_FALSE(evaluateStandalone("STEP (TIME,0,0,1,1)", 0.0, nullptr, nullptr, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]).substr(0, 64),
            "<command line>: error: blank between STEP and '(' at column 5 of");
}

}  // namespace
}  // namespace openmss::expr
