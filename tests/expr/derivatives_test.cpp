// Exact first derivatives (reverse mode) against central finite differences.
//
// Every argument of a function under test is a host value (VARVAL(k)), so the check covers
// the partial with respect to each argument, not only the first. Points are drawn at random
// (fixed seed) away from the kinks and jumps of each function: at least 100 finite-difference
// steps from every branch point. The finite difference is central, Richardson-extrapolated,
// with step 1e-4 * max(1, |x|) (see expr_test_support.hpp); agreement is 1e-6 relative.

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::checkAllDerivatives;
using testing::parseOk;

class Sampler {
 public:
  double uniform(double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine_);
  }
  // A magnitude in [low, high] with a random sign.
  double signedMagnitude(double low, double high) {
    return (uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * uniform(low, high);
  }
  // A value in [low, high] whose fractional part is at least `margin` from 0 and from 1/2.
  double awayFromWholeAndHalf(double low, double high, double margin) {
    while (true) {
      const double x = uniform(low, high);
      const double twice = 2.0 * x;
      if (std::abs(twice - std::round(twice)) > 2.0 * margin) return x;
    }
  }

 private:
  std::mt19937 engine_{20240611u};
};

// "NAME(VARVAL(1), ..., VARVAL(n))".
std::string callOfHostValues(const std::string& name, std::size_t count) {
  std::string text = name + "(";
  for (std::size_t k = 1; k <= count; ++k) {
    if (k > 1) text += (name == "IF" && k == 2) ? " : " : ", ";
    text += "VARVAL(" + std::to_string(k) + ")";
  }
  return text + ")";
}

struct FunctionCase {
  std::string name;
  std::function<std::vector<double>(Sampler&)> sample;
};

std::vector<FunctionCase> functionCases() {
  const auto one = [](double low, double high) {
    return [=](Sampler& s) { return std::vector<double>{s.uniform(low, high)}; };
  };
  // STEP-like (x, x0, h0, x1, h1) with x inside or outside the transition, away from its ends.
  const auto stepArguments = [](Sampler& s) {
    const double x0 = s.uniform(-1.0, 0.0);
    const double width = s.uniform(0.5, 2.0);
    const double where = s.uniform(0.0, 1.0) < 0.8 ? s.uniform(0.05, 0.95)
                                                   : (s.uniform(0.0, 1.0) < 0.5 ? -0.5 : 1.5);
    return std::vector<double>{x0 + where * width, x0, s.uniform(-2.0, 2.0), x0 + width,
                               s.uniform(-2.0, 2.0)};
  };
  const auto series = [](int fixed, int coefficients) {
    return [=](Sampler& s) {
      std::vector<double> args;
      for (int k = 0; k < fixed + coefficients; ++k) args.push_back(s.uniform(-1.5, 1.5));
      return args;
    };
  };
  return {
      {"ABS", [](Sampler& s) { return std::vector<double>{s.signedMagnitude(0.1, 3.0)}; }},
      {"SQRT", one(0.1, 5.0)},
      {"EXP", one(-2.0, 2.0)},
      {"LOG", one(0.1, 5.0)},
      {"LOG10", one(0.1, 5.0)},
      {"SIN", one(-3.0, 3.0)},
      {"COS", one(-3.0, 3.0)},
      {"TAN", one(-1.2, 1.2)},
      {"ASIN", one(-0.9, 0.9)},
      {"ACOS", one(-0.9, 0.9)},
      {"ATAN", one(-3.0, 3.0)},
      {"ATAN2",
       // Keep away from the origin and from the cut along the negative x axis.
       [](Sampler& s) {
         return std::vector<double>{s.signedMagnitude(0.2, 2.0), s.uniform(-2.0, 2.0)};
       }},
      {"SINH", one(-2.0, 2.0)},
      {"COSH", one(-2.0, 2.0)},
      {"TANH", one(-2.0, 2.0)},
      {"MAX",
       [](Sampler& s) {
         const double a = s.uniform(-2.0, 2.0);
         return std::vector<double>{a, a + s.signedMagnitude(0.1, 1.0),
                                    a + s.signedMagnitude(1.2, 2.0)};
       }},
      {"MIN",
       [](Sampler& s) {
         const double a = s.uniform(-2.0, 2.0);
         return std::vector<double>{a, a + s.signedMagnitude(0.1, 1.0),
                                    a + s.signedMagnitude(1.2, 2.0)};
       }},
      {"MOD",
       [](Sampler& s) {
         const double b = s.signedMagnitude(0.5, 2.0);
         const double quotient = s.awayFromWholeAndHalf(-4.0, 4.0, 0.05);
         return std::vector<double>{quotient * b, b};
       }},
      {"SIGN",
       [](Sampler& s) {
         return std::vector<double>{s.signedMagnitude(0.1, 3.0), s.signedMagnitude(0.1, 3.0)};
       }},
      {"DIM",
       [](Sampler& s) {
         const double a = s.uniform(-2.0, 2.0);
         return std::vector<double>{a, a + s.signedMagnitude(0.1, 2.0)};
       }},
      {"AINT",
       [](Sampler& s) { return std::vector<double>{s.awayFromWholeAndHalf(-3.0, 3.0, 0.05)}; }},
      {"ANINT",
       [](Sampler& s) { return std::vector<double>{s.awayFromWholeAndHalf(-3.0, 3.0, 0.05)}; }},
      {"STEP", stepArguments},
      {"STEP5", stepArguments},
      {"HAVSIN", stepArguments},
      {"SHF", series(6, 0)},
      {"POLY", series(2, 5)},
      {"CHEBY", series(2, 6)},
      {"FORCOS", series(3, 4)},
      {"FORSIN", series(3, 4)},
      {"SWEEP",
       [](Sampler& s) {
         const double x0 = s.uniform(0.5, 1.0);
         const double x1 = x0 + s.uniform(1.0, 2.0);
         const double dx = s.uniform(0.1, 0.3);
         // Before the ramp ends, between x0 and x1, or after x1.
         const double pick = s.uniform(0.0, 1.0);
         const double x = pick < 0.2   ? s.uniform(0.02, dx - 0.02)
                          : pick < 0.4 ? s.uniform(dx + 0.02, x0 - 0.02)
                          : pick < 0.8 ? s.uniform(x0 + 0.02, x1 - 0.02)
                                       : s.uniform(x1 + 0.02, x1 + 1.0);
         return std::vector<double>{x,  s.uniform(0.5, 2.0), x0, s.uniform(0.5, 2.0),
                                    x1, s.uniform(2.0, 4.0), dx};
       }},
      {"IMPACT",
       [](Sampler& s) {
         const double x1 = s.uniform(0.5, 1.0);
         const double d = s.uniform(0.05, 0.2);
         // Penetration inside or beyond the damping ramp, approaching (xdot < 0) so that the
         // force stays positive and away from the max(0, ...) kink.
         const double penetration =
             s.uniform(0.0, 1.0) < 0.5 ? s.uniform(0.01, d - 0.01) : s.uniform(d + 0.01, 0.4);
         return std::vector<double>{
             x1 - penetration,    s.uniform(-1.0, -0.1), x1, s.uniform(10.0, 100.0),
             s.uniform(1.0, 2.5), s.uniform(1.0, 10.0),  d};
       }},
      {"BISTOP",
       [](Sampler& s) {
         const double x1 = s.uniform(-1.0, 0.0);
         const double x2 = x1 + s.uniform(0.5, 1.0);
         const double d = s.uniform(0.05, 0.2);
         const double penetration =
             s.uniform(0.0, 1.0) < 0.5 ? s.uniform(0.01, d - 0.01) : s.uniform(d + 0.01, 0.4);
         const bool lower = s.uniform(0.0, 1.0) < 0.5;
         const double x = lower ? x1 - penetration : x2 + penetration;
         const double xdot = lower ? s.uniform(-1.0, -0.1) : s.uniform(0.1, 1.0);
         return std::vector<double>{
             x, xdot, x1, x2, s.uniform(10.0, 100.0), s.uniform(1.0, 2.5), s.uniform(1.0, 10.0), d};
       }},
      {"IF",
       [](Sampler& s) {
         // A zero condition is a jump in e1; see IfAtZeroSelectsTheMiddleBranch.
         const double condition = s.signedMagnitude(0.1, 1.0);
         return std::vector<double>{condition, s.uniform(-2.0, 2.0), s.uniform(-2.0, 2.0),
                                    s.uniform(-2.0, 2.0)};
       }},
  };
}

TEST(Derivatives, EveryBuiltinWithRespectToEveryArgument) {
  Sampler sampler;
  for (const FunctionCase& function : functionCases()) {
    const std::size_t arity = function.sample(sampler).size();
    const std::string text = callOfHostValues(function.name, arity);
    const Expression e = parseOk(text);
    ASSERT_EQ(e.hostCalls().size(), arity) << text;
    for (int trial = 0; trial < 25; ++trial) {
      const std::vector<double> host = function.sample(sampler);
      checkAllDerivatives(e, host, 0.0, text + " trial " + std::to_string(trial));
    }
  }
}

TEST(Derivatives, OperatorsAndTime) {
  Sampler sampler;
  const char* texts[] = {
      "VARVAL(1) + VARVAL(2) - VARVAL(1) * VARVAL(2) / (1 + VARVAL(2)**2)",
      "-VARVAL(1)**-VARVAL(2)",
      "VARVAL(1)**VARVAL(2)",
      "VARVAL(1)**3 - 2**VARVAL(2)",
      "TIME**TIME",
      "SIN(TIME*VARVAL(1))**2 / (1 + VARVAL(2)**2) - ATAN2(VARVAL(1), TIME+3)",
      "STEP(TIME, 0, VARVAL(1), 3, VARVAL(2))",
      "POLY(TIME, 1, VARVAL(1), 2, 0, -1) * EXP(-TIME)",
      "IF(TIME - 1.5: VARVAL(1)*TIME, 0, VARVAL(2)/TIME)",
      "VARVAL(1) * 0 + VARVAL(2)",
  };
  for (const char* text : texts) {
    const Expression e = parseOk(text);
    for (int trial = 0; trial < 25; ++trial) {
      const std::vector<double> host = {sampler.uniform(0.5, 2.0), sampler.uniform(0.5, 2.0)};
      double time = sampler.uniform(0.2, 2.8);
      if (std::abs(time - 1.5) < 0.01) time += 0.1;
      checkAllDerivatives(
          e,
          std::vector<double>(host.begin(),
                              host.begin() + static_cast<std::ptrdiff_t>(e.hostCalls().size())),
          time, text);
    }
  }
}

TEST(Derivatives, RealDataSetExpressions) {
  Sampler sampler;
  {
    // SFORCE contact: gap x = 0.6066 - DM, xdot = -VR; penetrations both inside the damping
    // ramp (d = 1e-6 is tiny, so mostly beyond it) and approaching velocities.
    const Expression e = parseOk(
        "-IMPACT(0.1+0.5066-DM(68,64), -VR(78,81), 0.10085, 1.0E+007, 1.0, 1.0E+006, "
        "1.0E-006)");
    for (int trial = 0; trial < 25; ++trial) {
      checkAllDerivatives(e, {0.5066 + sampler.uniform(0.001, 0.01), sampler.uniform(0.01, 1.0)},
                          0.0, "IMPACT sforce");
    }
  }
  {
    const Expression e = parseOk("1422.0 * DM(0409, 0109) ** (-1.4) - 185.4");
    for (int trial = 0; trial < 25; ++trial) {
      checkAllDerivatives(e, {sampler.uniform(0.5, 3.0)}, 0.0, "gas spring");
    }
  }
  {
    const Expression e =
        parseOk("-0.4*SIGN(1.0,WZ(46,23,23))*5.6*(JOINT(1,0,1,23)-ABS(JOINT(1,0,4,23)))");
    for (int trial = 0; trial < 25; ++trial) {
      checkAllDerivatives(e,
                          {sampler.signedMagnitude(0.1, 2.0), sampler.uniform(1.0, 5.0),
                           sampler.signedMagnitude(0.1, 1.0)},
                          0.0, "joint friction");
    }
  }
  {
    const Expression e = parseOk("IF(MODE-5: 0, -DIF(101)-1E7*(DZ(9006900,1001,1001)-1317.2), 0)");
    checkAllDerivatives(e, {5.0, 0.3, 1317.3}, 0.0, "IF on MODE");
    std::vector<double> dHost(3);
    double dTime = 0.0;
    const double host[3] = {5.0, 0.3, 1317.3};
    e.evaluate(host, 0.0, dHost.data(), &dTime);
    EXPECT_DOUBLE_EQ(dHost[0], 0.0);
    EXPECT_DOUBLE_EQ(dHost[1], -1.0);
    EXPECT_DOUBLE_EQ(dHost[2], -1e7);
  }
}

TEST(Derivatives, AtBranchPointsTheSelectedPieceIsDifferentiated) {
  const Expression e = parseOk("STEP(VARVAL(1), 0, 1, 1, 3)");
  std::vector<double> d(1);
  double dTime = 0.0;
  double x = 0.0;
  e.evaluate(&x, 0.0, d.data(), &dTime);
  EXPECT_DOUBLE_EQ(d[0], 0.0);
  x = 0.5;  // midpoint slope: a * 6 s (1 - s) / (x1 - x0) = 2 * 1.5
  e.evaluate(&x, 0.0, d.data(), &dTime);
  EXPECT_DOUBLE_EQ(d[0], 3.0);
  const Expression absolute = parseOk("ABS(VARVAL(1))");
  x = 0.0;
  absolute.evaluate(&x, 0.0, d.data(), &dTime);
  EXPECT_DOUBLE_EQ(d[0], 1.0);
  const Expression outside = parseOk("IMPACT(VARVAL(1), -1, 1, 100, 2, 10, 0.1)");
  x = 1.5;
  outside.evaluate(&x, 0.0, d.data(), &dTime);
  EXPECT_DOUBLE_EQ(d[0], 0.0);
  EXPECT_DOUBLE_EQ(dTime, 0.0);
}

TEST(Derivatives, IfAtZeroSelectsTheMiddleBranch) {
  const Expression e = parseOk("IF(VARVAL(1) : VARVAL(2), VARVAL(3)**2, VARVAL(4))");
  const double host[4] = {0.0, 5.0, 3.0, 7.0};
  double d[4] = {-1.0, -1.0, -1.0, -1.0};
  double dTime = -1.0;
  EXPECT_DOUBLE_EQ(e.evaluate(host, 0.0, d, &dTime), 9.0);
  EXPECT_DOUBLE_EQ(d[0], 0.0);
  EXPECT_DOUBLE_EQ(d[1], 0.0);
  EXPECT_DOUBLE_EQ(d[2], 6.0);
  EXPECT_DOUBLE_EQ(d[3], 0.0);
  EXPECT_DOUBLE_EQ(dTime, 0.0);
}

TEST(Derivatives, NullOutputPointersAreAllowed) {
  const Expression e = parseOk("DM(1,2)*TIME");
  const double dm = 2.0;
  EXPECT_DOUBLE_EQ(e.evaluate(&dm, 3.0, nullptr, nullptr), 6.0);
}

}  // namespace
}  // namespace openmss::expr
