// Second-order time jets (value, d/dt, d2/dt2) of TIME-only expressions, as MOTION needs:
// d/dt against finite differences of the value, d2/dt2 against finite differences of the exact
// first derivative, both central and Richardson-extrapolated with step 1e-4 * max(1, |t|),
// agreeing to 1e-6 relative. Times are chosen away from every kink of the expressions.

#include <cmath>
#include <limits>
#include <numbers>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::centralDifference;
using testing::expectDerivativeNear;
using testing::parseOk;
using testing::stepFor;

TEST(TimeJets, AgreeWithFiniteDifferencesForEveryFunction) {
  const char* texts[] = {
      "3*TIME - 1",
      "SIN(2*TIME) * EXP(-TIME)",
      "TIME**3",
      "TIME**TIME",
      "2**TIME",
      "-TIME**-2",
      "SQRT(1+TIME**2)",
      "LOG(2+TIME)",
      "LOG10(2+TIME)",
      "TAN(TIME/3)",
      "ASIN(TIME/4)",
      "ACOS(TIME/4)",
      "ATAN(TIME)",
      "ATAN2(SIN(TIME), 2+COS(TIME))",
      "SINH(TIME)",
      "COSH(TIME)",
      "TANH(TIME)",
      "1/(1+TIME**2)",
      "ABS(TIME-5)",
      "MAX(TIME, 2-TIME, 0.5*TIME**2)",
      "MIN(TIME, 2-TIME)",
      "MOD(TIME**2, 17)",
      "SIGN(TIME**2, TIME-5)",
      "DIM(TIME**2, 1)",
      "AINT(TIME) + ANINT(TIME) + TIME",
      "STEP(TIME, 0, 1, 4, 3)",
      "STEP5(TIME, 0, 1, 4, 3)",
      "HAVSIN(TIME, 0, 1, 4, 3)",
      "SHF(TIME, 0.3, 2, 3, 0.1, 4)",
      "POLY(TIME, 1, 1, 2, 3, 4)",
      "POLY(TIME, 0, 0, 360D)",
      "CHEBY(TIME/4, 0.1, 1, 2, 3, 4, 5)",
      "FORCOS(TIME, 0, 2, 1, 2, 3)",
      "FORSIN(TIME, 0.5, 30D, 1, 2, 3)",
      "SWEEP(TIME, 1.0, 0.0, 2.0, 5.0, 6.0, 0.01)",
      "SWEEP(TIME, 1.0, 1.0, 0.2, 2.0, 0.6, 3.0)",
      "IMPACT(TIME, -1, 4, 100, 2.5, 10, 0.5)",
      "BISTOP(TIME, -TIME, 0.5, 1.2, 100, 2, 10, 0.3)",
      "IF(TIME-2: TIME**2, 0, SIN(TIME))",
      "STEP(TIME, 1, 0, 3, SIN(TIME))",
  };
  const double times[] = {0.35, 0.8, 1.7, 2.3, 3.1, 3.6};
  for (const char* text : texts) {
    const Expression e = parseOk(text);
    for (double t : times) {
      const TimeJet jet = e.evaluateTimeJet(t);
      const std::string what = std::string(text) + " at t = " + std::to_string(t);
      EXPECT_DOUBLE_EQ(jet.value, e.evaluate(nullptr, t)) << what;
      double dTime = 0.0;
      e.evaluate(nullptr, t, nullptr, &dTime);
      EXPECT_NEAR(jet.d1, dTime, 1e-12 * std::max(1.0, std::abs(dTime))) << what;
      const auto value = [&](double x) { return e.evaluate(nullptr, x); };
      const auto rate = [&](double x) {
        double d = 0.0;
        e.evaluate(nullptr, x, nullptr, &d);
        return d;
      };
      expectDerivativeNear(jet.d1, centralDifference(value, t, stepFor(t)), std::abs(jet.value),
                           what + " d1");
      expectDerivativeNear(jet.d2, centralDifference(rate, t, stepFor(t)), std::abs(jet.d1),
                           what + " d2");
    }
  }
}

TEST(TimeJets, ClosedForms) {
  const TimeJet poly = parseOk("POLY(TIME, 0, 0, 360D)").evaluateTimeJet(0.5);
  EXPECT_NEAR(poly.value, std::numbers::pi, 1e-15);
  EXPECT_NEAR(poly.d1, 2.0 * std::numbers::pi, 1e-15);
  EXPECT_DOUBLE_EQ(poly.d2, 0.0);
  // STEP(TIME, 0, 0, 1, 1) = 3t^2 - 2t^3 inside: at t = 1/4, 0.15625, 1.125, 3.
  const TimeJet step = parseOk("STEP(TIME,0,0,1,1)").evaluateTimeJet(0.25);
  EXPECT_DOUBLE_EQ(step.value, 0.15625);
  EXPECT_DOUBLE_EQ(step.d1, 1.125);
  EXPECT_DOUBLE_EQ(step.d2, 3.0);
  const TimeJet constant = parseOk("2*PI").evaluateTimeJet(1.0);
  EXPECT_DOUBLE_EQ(constant.value, 2.0 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(constant.d1, 0.0);
  EXPECT_DOUBLE_EQ(constant.d2, 0.0);
  const TimeJet sine = parseOk("SIN(3*TIME)").evaluateTimeJet(0.2);
  EXPECT_DOUBLE_EQ(sine.d1, 3.0 * std::cos(0.6));
  EXPECT_DOUBLE_EQ(sine.d2, -9.0 * std::sin(0.6));
}

TEST(TimeJets, HostCallsBreakThePreconditionAndGiveNaN) {
  const TimeJet jet = parseOk("DX(1)*TIME").evaluateTimeJet(1.0);
  EXPECT_TRUE(std::isnan(jet.value));
  EXPECT_TRUE(std::isnan(jet.d1));
  EXPECT_TRUE(std::isnan(jet.d2));
}

}  // namespace
}  // namespace openmss::expr
