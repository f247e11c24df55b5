// Grammar, precedence, numbers, names and host-call collection.

#include <numbers>

#include "expr/expression.hpp"
#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::parseOk;
using testing::valueOf;

constexpr double kPi = std::numbers::pi;

TEST(ExpressionPrecedence, PowerBindsTighterThanUnaryMinusOnItsLeft) {
  EXPECT_DOUBLE_EQ(valueOf("-2**2"), -4.0);
  EXPECT_DOUBLE_EQ(valueOf("-3**2"), -9.0);
  EXPECT_DOUBLE_EQ(valueOf("0-2**2"), -4.0);
}

TEST(ExpressionPrecedence, PowerIsRightAssociative) {
  EXPECT_DOUBLE_EQ(valueOf("2**3**2"), 512.0);
  EXPECT_DOUBLE_EQ(valueOf("(2**3)**2"), 64.0);
}

TEST(ExpressionPrecedence, SignOnTheRightOfPowerBelongsToTheExponent) {
  EXPECT_DOUBLE_EQ(valueOf("2**-1"), 0.5);
  EXPECT_DOUBLE_EQ(valueOf("2**+3"), 8.0);
}

TEST(ExpressionPrecedence, MinusAPowerMinusB) {
  // -A**-B = -(A**(-B)) with A = 2 (TIME), B = 1.
  EXPECT_DOUBLE_EQ(valueOf("-TIME**-1", 2.0), -0.5);
  // -A**-B**-C = -(A**(-(B**(-C)))) with A = B = 2, C = 1: -(2**(-0.5)).
  EXPECT_DOUBLE_EQ(valueOf("-2**-2**-1"), -std::pow(2.0, -0.5));
}

TEST(ExpressionPrecedence, MultiplicationBeforeAdditionLeftToRight) {
  EXPECT_DOUBLE_EQ(valueOf("2+3*4"), 14.0);
  EXPECT_DOUBLE_EQ(valueOf("(2+3)*4"), 20.0);
  EXPECT_DOUBLE_EQ(valueOf("1-2-3"), -4.0);
  EXPECT_DOUBLE_EQ(valueOf("8/4/2"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("2*-3"), -6.0);
  EXPECT_DOUBLE_EQ(valueOf("2- -3"), 5.0);
  EXPECT_DOUBLE_EQ(valueOf("-(1-4)"), 3.0);
  EXPECT_DOUBLE_EQ(valueOf("2*3**2"), 18.0);
}

TEST(ExpressionPrecedence, DivisionIsReal) {
  // Unlike FORTRAN integer arithmetic, every number is a double: 1/2 is 0.5.
  EXPECT_DOUBLE_EQ(valueOf("1/2"), 0.5);
  EXPECT_DOUBLE_EQ(valueOf("(1-TIME)*30/PI", 0.5), 15.0 / kPi);
}

TEST(ExpressionNumbers, FortranForms) {
  EXPECT_DOUBLE_EQ(valueOf("1"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("1."), 1.0);
  EXPECT_DOUBLE_EQ(valueOf(".5"), 0.5);
  EXPECT_DOUBLE_EQ(valueOf("1.E-3"), 1e-3);
  EXPECT_DOUBLE_EQ(valueOf("1.0E+007"), 1e7);
  EXPECT_DOUBLE_EQ(valueOf("2.5e2"), 250.0);
  EXPECT_DOUBLE_EQ(valueOf("0409"), 409.0);
}

TEST(ExpressionNumbers, TrailingDMeansDegrees) {
  EXPECT_DOUBLE_EQ(valueOf("90D"), kPi / 2.0);
  EXPECT_DOUBLE_EQ(valueOf("360d"), 2.0 * kPi);
  EXPECT_DOUBLE_EQ(valueOf("1.5E2D"), 150.0 * kPi / 180.0);
  // A D directly followed by a signed number is ambiguous (FORTRAN exponent or degrees and a
  // subtraction) and refused; with a blank after the D it is degrees.
  EXPECT_DOUBLE_EQ(valueOf("30D -1"), kPi / 6.0 - 1.0);
  EXPECT_DOUBLE_EQ(valueOf("30D-TIME", 1.0), kPi / 6.0 - 1.0);
  EXPECT_DOUBLE_EQ(valueOf("IF(1 -85D: 1, 2, 3)"), 1.0);
}

TEST(ExpressionNames, ConstantsAndCaseInsensitivity) {
  EXPECT_DOUBLE_EQ(valueOf("PI"), kPi);
  EXPECT_DOUBLE_EQ(valueOf("pi"), kPi);
  EXPECT_DOUBLE_EQ(valueOf("DTOR"), kPi / 180.0);
  EXPECT_DOUBLE_EQ(valueOf("RTOD"), 180.0 / kPi);
  EXPECT_DOUBLE_EQ(valueOf("Time", 3.5), 3.5);
  EXPECT_DOUBLE_EQ(valueOf("sin(pi/2)"), 1.0);
  EXPECT_DOUBLE_EQ(valueOf("Step(time,0,0,1,1)", 0.5), 0.5);
}

TEST(ExpressionNames, BlanksAreAllowedExceptBeforeTheParenthesis) {
  EXPECT_DOUBLE_EQ(valueOf("  STEP( TIME , 0 ,0,1 , 1 )  ", 0.5), 0.5);
  EXPECT_DOUBLE_EQ(valueOf("2 ** 3"), 8.0);
  EXPECT_DOUBLE_EQ(valueOf("2\t*\n3"), 6.0);
}

TEST(ExpressionHostCalls, RealExpressionsAndTheirHostCalls) {
  {
    const Expression e = parseOk("POLY(TIME, 0, 0, 360D)");
    EXPECT_TRUE(e.hostCalls().empty());
    EXPECT_TRUE(e.dependsOnTime());
    EXPECT_NEAR(e.evaluate(nullptr, 0.25), 0.5 * kPi, 1e-15);
  }
  {
    const Expression e = parseOk("POLY(VR(408, 109), 0, 0, -0.2)");
    ASSERT_EQ(e.hostCalls().size(), 1u);
    EXPECT_EQ(e.hostCalls()[0].name, "VR");
    EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{408, 109}));
    EXPECT_EQ(e.hostCalls()[0].column, 6);
    EXPECT_FALSE(e.dependsOnTime());
    const double vr = 3.0;
    EXPECT_DOUBLE_EQ(e.evaluate(&vr, 0.0), -0.6);
  }
  {
    const Expression e = parseOk("1422.0 * DM(0409, 0109) ** (-1.4) - 185.4");
    ASSERT_EQ(e.hostCalls().size(), 1u);
    EXPECT_EQ(e.hostCalls()[0].name, "DM");
    EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{409, 109}));
    const double dm = 2.0;
    EXPECT_DOUBLE_EQ(e.evaluate(&dm, 0.0), 1422.0 * std::pow(2.0, -1.4) - 185.4);
  }
  {
    const Expression e = parseOk("ORIENT(27,1,0201,0101)");
    ASSERT_EQ(e.hostCalls().size(), 1u);
    EXPECT_EQ(e.hostCalls()[0].name, "ORIENT");
    EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{27, 1, 201, 101}));
    const double q = 0.25;
    EXPECT_DOUBLE_EQ(e.evaluate(&q, 0.0), 0.25);
  }
  {
    const Expression e = parseOk("JOINT(1,0,2,0)");
    ASSERT_EQ(e.hostCalls().size(), 1u);
    EXPECT_EQ(e.hostCalls()[0].name, "JOINT");
    EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{1, 0, 2, 0}));
  }
  {
    const Expression e = parseOk(
        "-IMPACT(0.1+0.5066-DM(68,64), -VR(78,81), 0.10085, 1.0E+007, 1.0, 1.0E+006, "
        "1.0E-006)");
    ASSERT_EQ(e.hostCalls().size(), 2u);
    EXPECT_EQ(e.hostCalls()[0].name, "DM");
    EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{68, 64}));
    EXPECT_EQ(e.hostCalls()[0].column, 20);
    EXPECT_EQ(e.hostCalls()[1].name, "VR");
    EXPECT_EQ(e.hostCalls()[1].args, (std::vector<long>{78, 81}));
    EXPECT_EQ(e.hostCalls()[1].column, 32);
    // Gap x = 0.6066 - DM = 0.1 (penetration 0.00085, beyond d = 1e-6): the force is
    // k * 0.00085 + cmax * VR.
    const double host[2] = {0.5066, 0.01};
    EXPECT_NEAR(e.evaluate(host, 0.0), -(1e7 * 0.00085 + 1e6 * 0.01), 1e-6);
  }
  {
    const Expression e = parseOk("STEP(TIME,0,0,1,1)");
    EXPECT_TRUE(e.hostCalls().empty());
    EXPECT_DOUBLE_EQ(e.evaluate(nullptr, 0.5), 0.5);
  }
}

TEST(ExpressionHostCalls, DeduplicationKeepsFirstAppearanceOrder) {
  const Expression e = parseOk("DM(1,2) + dm(01, 2)*DX(1,2) + DM(1) + DX(1,2) + MODE + MODE");
  ASSERT_EQ(e.hostCalls().size(), 4u);
  EXPECT_EQ(e.hostCalls()[0].name, "DM");
  EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{1, 2}));
  EXPECT_EQ(e.hostCalls()[1].name, "DX");
  EXPECT_EQ(e.hostCalls()[2].name, "DM");
  EXPECT_EQ(e.hostCalls()[2].args, (std::vector<long>{1}));
  EXPECT_EQ(e.hostCalls()[3].name, "MODE");
  EXPECT_TRUE(e.hostCalls()[3].args.empty());
  const double host[4] = {2.0, 3.0, 5.0, 7.0};
  EXPECT_DOUBLE_EQ(e.evaluate(host, 0.0), 2.0 + 2.0 * 3.0 + 5.0 + 3.0 + 7.0 + 7.0);
}

TEST(ExpressionHostCalls, PlaceholderZeroAndNegativeIntegersAreKeptAsWritten) {
  const Expression e = parseOk("DX(21,0,32) + VX(1, 0, 0, 5) + ARYVAL(3, 2) + FX(23,0,432)");
  ASSERT_EQ(e.hostCalls().size(), 4u);
  EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{21, 0, 32}));
  EXPECT_EQ(e.hostCalls()[1].args, (std::vector<long>{1, 0, 0, 5}));
  EXPECT_EQ(e.hostCalls()[2].args, (std::vector<long>{3, 2}));
  EXPECT_EQ(e.hostCalls()[3].args, (std::vector<long>{23, 0, 432}));
}

TEST(ExpressionHostCalls, AnalysisVariablesAreZeroArgumentHostCalls) {
  const Expression e = parseOk("IF(MODE-5: 0, DIF(101), 0) + HSIZE + ORDER + NJAC + NRHS + CPU");
  ASSERT_EQ(e.hostCalls().size(), 7u);
  EXPECT_EQ(e.hostCalls()[0].name, "MODE");
  EXPECT_EQ(e.hostCalls()[1].name, "DIF");
  EXPECT_EQ(e.hostCalls()[6].name, "CPU");
}

TEST(ExpressionHostCalls, EveryCatalogueHostFunctionParsesWithItsMinimumArgumentCount) {
  const char* oneArg[] = {
      "DX", "DY", "DZ",   "DM",    "VX",   "VY",     "VZ",    "VM",   "VR",    "WX",   "WY",
      "WZ", "WM", "ACCX", "ACCY",  "ACCZ", "ACCM",   "WDTX",  "WDTY", "WDTZ",  "WDTM", "AX",
      "AY", "AZ", "PSI",  "THETA", "PHI",  "YAW",    "PITCH", "ROLL", "FX",    "FY",   "FZ",
      "FM", "TX", "TY",   "TZ",    "TM",   "VARVAL", "DIF",   "DIF1", "SENVAL"};
  for (const char* name : oneArg) {
    const Expression e = parseOk(std::string(name) + "(5)");
    ASSERT_EQ(e.hostCalls().size(), 1u) << name;
    EXPECT_EQ(e.hostCalls()[0].name, name);
  }
  const char* fourArgs[] = {"JOINT", "JPRIM", "MOTION",   "SFORCE", "SPDP",   "BUSH",
                            "FIELD", "BEAM",  "VFORCE",   "VTORQ",  "GFORCE", "NFORCE",
                            "PTCV",  "CVCV",  "ORIENT"};
  for (const char* name : fourArgs) {
    EXPECT_EQ(parseOk(std::string(name) + "(1,0,2,0)").hostCalls().size(), 1u) << name;
  }
  for (const char* name : {"ARYVAL", "PINVAL", "POUVAL", "FRICTION"}) {
    EXPECT_EQ(parseOk(std::string(name) + "(1,2)").hostCalls().size(), 1u) << name;
  }
  EXPECT_EQ(parseOk("INCANG(1,2,3)").hostCalls().size(), 1u);
}

TEST(ExpressionProgram, ConstantSubtreesAreFolded) {
  const Expression e = parseOk("IF(1: DM(1,2), 2*PI, 3) + SIN(30D)*TIME");
  // The constant condition keeps only e4 = 3, but DM stays in the host list.
  ASSERT_EQ(e.hostCalls().size(), 1u);
  const double dm = 123.0;
  EXPECT_DOUBLE_EQ(e.evaluate(&dm, 2.0), 3.0 + 0.5 * 2.0);
  EXPECT_FALSE(parseOk("IF(-1: 1, TIME, 2)").dependsOnTime());
}

TEST(ExpressionProgram, CopiesAndMovesEvaluateTheSame) {
  const Expression original = parseOk("STEP(TIME, 0, 1, 2, 3) * DM(1,2)");
  Expression copy = original;
  Expression assigned;
  assigned = original;
  Expression moved = std::move(copy);
  const double dm = 1.5;
  EXPECT_DOUBLE_EQ(moved.evaluate(&dm, 1.0), original.evaluate(&dm, 1.0));
  EXPECT_DOUBLE_EQ(assigned.evaluate(&dm, 1.0), original.evaluate(&dm, 1.0));
  EXPECT_EQ(assigned.text(), "STEP(TIME, 0, 1, 2, 3) * DM(1,2)");
  EXPECT_EQ(assigned.hostCalls().size(), 1u);
}

TEST(ExpressionProgram, DefaultConstructedEvaluatesToZero) {
  const Expression e;
  EXPECT_EQ(e.text(), "");
  EXPECT_TRUE(e.hostCalls().empty());
  EXPECT_DOUBLE_EQ(e.evaluate(nullptr, 1.0), 0.0);
}

}  // namespace
}  // namespace openmss::expr
