// Values of every built-in function against closed forms and hand-computed numbers, including
// the branch points of the piecewise definitions.

#include <cmath>
#include <numbers>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::valueOf;

constexpr double kPi = std::numbers::pi;

TEST(BuiltinValues, MathIntrinsics) {
  EXPECT_DOUBLE_EQ(valueOf("ABS(-2.5)"), 2.5);
  EXPECT_DOUBLE_EQ(valueOf("SQRT(6.25)"), 2.5);
  EXPECT_DOUBLE_EQ(valueOf("EXP(1)"), std::numbers::e);
  EXPECT_DOUBLE_EQ(valueOf("LOG(EXP(2))"), 2.0);
  EXPECT_DOUBLE_EQ(valueOf("LOG10(1000)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("SIN(PI/6)"), 0.5);
  EXPECT_DOUBLE_EQ(valueOf("COS(PI/3)"), std::cos(kPi / 3.0));
  EXPECT_DOUBLE_EQ(valueOf("TAN(PI/4)"), std::tan(kPi / 4.0));
  EXPECT_DOUBLE_EQ(valueOf("ASIN(0.5)"), kPi / 6.0);
  EXPECT_DOUBLE_EQ(valueOf("ACOS(0.5)"), kPi / 3.0);
  EXPECT_DOUBLE_EQ(valueOf("ATAN(1)"), kPi / 4.0);
  EXPECT_DOUBLE_EQ(valueOf("ATAN2(1, -1)"), 3.0 * kPi / 4.0);
  EXPECT_DOUBLE_EQ(valueOf("ATAN2(-1, -1)"), -3.0 * kPi / 4.0);
  EXPECT_DOUBLE_EQ(valueOf("SINH(1)"), (std::numbers::e - 1.0 / std::numbers::e) / 2.0);
  EXPECT_DOUBLE_EQ(valueOf("COSH(1)"), (std::numbers::e + 1.0 / std::numbers::e) / 2.0);
  EXPECT_DOUBLE_EQ(valueOf("TANH(0.5)"), std::tanh(0.5));
}

TEST(BuiltinValues, MaxMinAcceptTwoOrMoreArguments) {
  EXPECT_DOUBLE_EQ(valueOf("MAX(1, 3)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("MAX(1, 3, 2)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("MIN(1, -3, 2)"), -3.0);
  EXPECT_DOUBLE_EQ(valueOf("MIN(4, 4)"), 4.0);
}

TEST(BuiltinValues, ModHasTheSignOfTheFirstOperand) {
  EXPECT_DOUBLE_EQ(valueOf("MOD(7, 3)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("MOD(-7, 3)"), -1.0);
  EXPECT_DOUBLE_EQ(valueOf("MOD(7, -3)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("MOD(-7, -3)"), -1.0);
  EXPECT_DOUBLE_EQ(valueOf("MOD(7.5, 2)"), 1.5);
  EXPECT_DOUBLE_EQ(valueOf("MOD(-7.5, 2)"), -1.5);
  EXPECT_DOUBLE_EQ(valueOf("MOD(6, 3)"), 0.0);
}

TEST(BuiltinValues, SignTransfersTheSignOfTheSecondOperand) {
  EXPECT_DOUBLE_EQ(valueOf("SIGN(3, 2)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("SIGN(-3, 2)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("SIGN(3, -2)"), -3.0);
  EXPECT_DOUBLE_EQ(valueOf("SIGN(-3, -2)"), -3.0);
  EXPECT_DOUBLE_EQ(valueOf("SIGN(-3, 0)"), 3.0);  // b = 0 counts as b >= 0
}

TEST(BuiltinValues, DimIsThePositiveDifference) {
  EXPECT_DOUBLE_EQ(valueOf("DIM(5, 3)"), 2.0);
  EXPECT_DOUBLE_EQ(valueOf("DIM(3, 5)"), 0.0);
  EXPECT_DOUBLE_EQ(valueOf("DIM(3, 3)"), 0.0);
  EXPECT_DOUBLE_EQ(valueOf("DIM(-1, -4)"), 3.0);
}

TEST(BuiltinValues, AintTruncatesAndAnintRoundsHalvesAwayFromZero) {
  EXPECT_DOUBLE_EQ(valueOf("AINT(2.7)"), 2.0);
  EXPECT_DOUBLE_EQ(valueOf("AINT(-2.7)"), -2.0);
  EXPECT_DOUBLE_EQ(valueOf("AINT(2.5)"), 2.0);
  EXPECT_DOUBLE_EQ(valueOf("AINT(-2.5)"), -2.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(2.5)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(-2.5)"), -3.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(0.5)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(-0.5)"), -1.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(2.49)"), 2.0);
  EXPECT_DOUBLE_EQ(valueOf("ANINT(-2.51)"), -3.0);
}

TEST(BuiltinValues, StepBranchPointsAndInterior) {
  // STEP(x, 0, 1, 1, 3): a = 2.
  EXPECT_DOUBLE_EQ(valueOf("STEP(-1, 0, 1, 1, 3)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("STEP(0, 0, 1, 1, 3)"), 1.0);        // x = x0
  EXPECT_DOUBLE_EQ(valueOf("STEP(0.5, 0, 1, 1, 3)"), 2.0);      // midpoint
  EXPECT_DOUBLE_EQ(valueOf("STEP(0.25, 0, 1, 1, 3)"), 1.3125);  // 1 + 2 * 1/16 * 5/2
  EXPECT_DOUBLE_EQ(valueOf("STEP(1, 0, 1, 1, 3)"), 3.0);        // x = x1
  EXPECT_DOUBLE_EQ(valueOf("STEP(2, 0, 1, 1, 3)"), 3.0);
  // Falling step and shifted interval: STEP(3, 2, 5, 6, 1), s = 1/4: 5 - 4 * 5/32.
  EXPECT_DOUBLE_EQ(valueOf("STEP(3, 2, 5, 6, 1)"), 5.0 - 4.0 * 0.15625);
}

TEST(BuiltinValues, Step5BranchPointsAndInterior) {
  EXPECT_DOUBLE_EQ(valueOf("STEP5(0, 0, 1, 1, 3)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("STEP5(0.5, 0, 1, 1, 3)"), 2.0);
  // s = 1/4: s^3 (10 - 15 s + 6 s^2) = 6.625 / 64.
  EXPECT_DOUBLE_EQ(valueOf("STEP5(0.25, 0, 1, 1, 3)"), 1.0 + 2.0 * 6.625 / 64.0);
  EXPECT_DOUBLE_EQ(valueOf("STEP5(1, 0, 1, 1, 3)"), 3.0);
}

TEST(BuiltinValues, HavsinBranchPointsAndInterior) {
  EXPECT_DOUBLE_EQ(valueOf("HAVSIN(0, 0, 1, 1, 3)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("HAVSIN(0.5, 0, 1, 1, 3)"), 2.0);
  // a = 2, b = 1, c = 1/4: 2 + sin(pi/4 - pi/2).
  EXPECT_DOUBLE_EQ(valueOf("HAVSIN(0.25, 0, 1, 1, 3)"), 2.0 - std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(valueOf("HAVSIN(1, 0, 1, 1, 3)"), 3.0);
}

TEST(BuiltinValues, Shf) {
  EXPECT_DOUBLE_EQ(valueOf("SHF(1, 0.5, 2, 3, 0.1, 4)"), 2.0 * std::sin(1.4) + 4.0);
}

TEST(BuiltinValues, PolyAndCheby) {
  EXPECT_DOUBLE_EQ(valueOf("POLY(2, 1, 1, 2, 3)"), 6.0);
  EXPECT_DOUBLE_EQ(valueOf("POLY(3, 1, 1, 2, 3)"), 1.0 + 4.0 + 12.0);
  EXPECT_DOUBLE_EQ(valueOf("POLY(3, 1, 7)"), 7.0);
  // u = 1/2: T0 = 1, T1 = 1/2, T2 = -1/2, T3 = -1.
  EXPECT_DOUBLE_EQ(valueOf("CHEBY(1.5, 1, 1, 2, 3, 4)"), 1.0 + 1.0 - 1.5 - 4.0);
  EXPECT_DOUBLE_EQ(valueOf("CHEBY(1.5, 1, 2)"), 2.0);
  // T4(u) = 8u^4 - 8u^2 + 1 at u = 0.3.
  EXPECT_DOUBLE_EQ(valueOf("CHEBY(0.3, 0, 0, 0, 0, 0, 1)"), 8 * 0.0081 - 8 * 0.09 + 1);
}

TEST(BuiltinValues, FourierSeries) {
  EXPECT_DOUBLE_EQ(valueOf("FORCOS(1, 0, 2, 1, 2, 3)"),
                   1.0 + 2.0 * std::cos(2.0) + 3.0 * std::cos(4.0));
  EXPECT_DOUBLE_EQ(valueOf("FORSIN(1, 0.5, 2, 1, 2, 3)"),
                   1.0 + 2.0 * std::sin(1.0) + 3.0 * std::sin(2.0));
  EXPECT_DOUBLE_EQ(valueOf("FORCOS(1, 0, 2, 5)"), 5.0);
  // Frequency in degrees per unit x: 90D at x = 1 is a quarter turn.
  EXPECT_NEAR(valueOf("FORSIN(1, 0, 90D, 0, 1)"), 1.0, 1e-15);
}

TEST(BuiltinValues, Sweep) {
  // a = 2, x0 = 1, f0 = 3, x1 = 5, f1 = 7, dx = 0.01.
  // Before x0: phase f0 x.
  EXPECT_NEAR(valueOf("SWEEP(0.3, 2, 1, 3, 5, 7, 0.01)"), 2.0 * std::sin(2.0 * kPi * 0.9), 1e-12);
  // Between: u = 1.5, phase 4.5 + 0.5 * 2.25 + 3 = 8.625.
  EXPECT_NEAR(valueOf("SWEEP(2.5, 2, 1, 3, 5, 7, 0.01)"), 2.0 * std::sin(2.0 * kPi * 8.625), 1e-12);
  // After x1: phase 7 x - 2 * 6.
  EXPECT_NEAR(valueOf("SWEEP(6.1, 2, 1, 3, 5, 7, 0.01)"), 2.0 * std::sin(2.0 * kPi * 30.7), 1e-11);
  // Amplitude ramp: STEP5 at the middle of 0..dx is 1/2.
  EXPECT_NEAR(valueOf("SWEEP(0.005, 2, 1, 3, 5, 7, 0.01)"), 0.5 * 2.0 * std::sin(2.0 * kPi * 0.015),
              1e-14);
  EXPECT_DOUBLE_EQ(valueOf("SWEEP(0, 2, 1, 3, 5, 7, 0.01)"), 0.0);
}

TEST(BuiltinValues, ImpactOutsideAtAndInsideContact) {
  // x1 = 1, k = 100, e = 2, cmax = 10, d = 0.1.
  EXPECT_DOUBLE_EQ(valueOf("IMPACT(1.2, -5, 1, 100, 2, 10, 0.1)"), 0.0);  // no contact
  EXPECT_DOUBLE_EQ(valueOf("IMPACT(1, -5, 1, 100, 2, 10, 0.1)"), 0.0);    // x = x1
  // Penetration 0.05 < d: damping STEP = 5 (midpoint); 100 * 0.0025 + 5 * 0.1.
  EXPECT_NEAR(valueOf("IMPACT(0.95, -0.1, 1, 100, 2, 10, 0.1)"), 0.75, 1e-14);
  // Separating fast: k term 0.25 minus damping 5 * 1 is negative, clipped to 0.
  EXPECT_DOUBLE_EQ(valueOf("IMPACT(0.95, 1, 1, 100, 2, 10, 0.1)"), 0.0);
  // Penetration 0.2 > d: full damping 10; 100 * 0.04 - 10 * 0.1.
  EXPECT_DOUBLE_EQ(valueOf("IMPACT(0.8, 0.1, 1, 100, 2, 10, 0.1)"), 3.0);
  // At penetration exactly d the damping is cmax.
  EXPECT_DOUBLE_EQ(valueOf("IMPACT(0.5, -1, 1, 100, 1, 10, 0.5)"), 50.0 + 10.0);
}

TEST(BuiltinValues, BistopBothStopsAndTheGap) {
  // x1 = 0, x2 = 1, k = 100, e = 2, cmax = 10, d = 0.1.
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(0.5, 3, 0, 1, 100, 2, 10, 0.1)"), 0.0);
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(0, 3, 0, 1, 100, 2, 10, 0.1)"), 0.0);
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(1, 3, 0, 1, 100, 2, 10, 0.1)"), 0.0);
  EXPECT_NEAR(valueOf("BISTOP(-0.05, -0.1, 0, 1, 100, 2, 10, 0.1)"), 0.75, 1e-14);
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(-0.2, 0.1, 0, 1, 100, 2, 10, 0.1)"), 3.0);
  EXPECT_NEAR(valueOf("BISTOP(1.05, 0.1, 0, 1, 100, 2, 10, 0.1)"), -0.75, 1e-14);
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(1.2, -0.1, 0, 1, 100, 2, 10, 0.1)"), -3.0);
  // Moving back out fast: -4 + 10 is positive, clipped to 0.
  EXPECT_DOUBLE_EQ(valueOf("BISTOP(1.2, -1, 0, 1, 100, 2, 10, 0.1)"), 0.0);
}

TEST(BuiltinValues, IfSelectsByTheSignOfTheFirstArgument) {
  EXPECT_DOUBLE_EQ(valueOf("IF(-1: 10, 20, 30)"), 10.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(0: 10, 20, 30)"), 20.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(2: 10, 20, 30)"), 30.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(TIME-1: 10, 20, 30)", 0.5), 10.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(TIME-1: 10, 20, 30)", 1.0), 20.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(TIME-1: 10, 20, 30)", 1.5), 30.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(TIME: IF(TIME+1: 1, 2, 3), 4, 5*TIME)", -0.5), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(TIME: IF(TIME+1: 1, 2, 3), 4, 5*TIME)", 2.0), 10.0);
}

TEST(BuiltinValues, IfEvaluatesOnlyTheSelectedBranch) {
  // The unselected branch is undefined (SQRT and LOG of a negative number); neither the value
  // nor the derivative may be touched by it.
  const Expression e = testing::parseOk("IF(TIME: SQRT(-TIME), 0, LOG(TIME))");
  double dTime = 0.0;
  EXPECT_DOUBLE_EQ(e.evaluate(nullptr, -4.0, nullptr, &dTime), 2.0);
  EXPECT_DOUBLE_EQ(dTime, -0.25);
  EXPECT_DOUBLE_EQ(e.evaluate(nullptr, 1.0, nullptr, &dTime), 0.0);
  EXPECT_DOUBLE_EQ(dTime, 1.0);
  const TimeJet jet = e.evaluateTimeJet(1.0);
  EXPECT_DOUBLE_EQ(jet.d2, -1.0);
}

TEST(BuiltinValues, LargeProgramsUseTheOwnedScratch) {
  // More instructions than the stack arrays hold.
  std::string text = "0";
  double expected = 0.0;
  for (int k = 1; k <= 200; ++k) {
    text += " + SIN(" + std::to_string(k) + "*TIME)";
    expected += std::sin(k * 0.1);
  }
  const Expression e = testing::parseOk(text);
  EXPECT_NEAR(e.evaluate(nullptr, 0.1), expected, 1e-12);
  double dTime = 0.0;
  e.evaluate(nullptr, 0.1, nullptr, &dTime);
  double expectedDerivative = 0.0;
  for (int k = 1; k <= 200; ++k) expectedDerivative += k * std::cos(k * 0.1);
  EXPECT_NEAR(dTime, expectedDerivative, 1e-9);
  EXPECT_NEAR(e.evaluateTimeJet(0.1).d1, expectedDerivative, 1e-9);
}

}  // namespace
}  // namespace openmss::expr
