// Vector expressions (expanded into scalar components by the parser) and USER(...) arguments.
// Vector results are compared with the same quantities computed here from the components
// (dot and cross products, norms written out by hand); every derivative is checked against
// central differences (expr_test_support.hpp: Richardson, step 1e-4 relative, 1e-6 relative).

#include <cmath>
#include <numbers>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::checkAllDerivatives;
using testing::parseOk;

std::vector<std::string> hostNames(const Expression& e) {
  std::vector<std::string> names;
  for (const HostCall& call : e.hostCalls()) names.push_back(call.name);
  return names;
}

TEST(Vectors, ComponentFunctionsBecomeThreeHostCallsWithTheSameArguments) {
  const Expression e = parseOk("DXYZ(1,2,3)*VXYZ(1,2,3)");
  EXPECT_EQ(hostNames(e), (std::vector<std::string>{"DX", "DY", "DZ", "VX", "VY", "VZ"}));
  for (const HostCall& call : e.hostCalls()) EXPECT_EQ(call.args, (std::vector<long>{1, 2, 3}));
  const Expression f = parseOk("WXYZ(4)*ACCXYZ(4)+WDTXYZ(4)*FXYZ(5,0,4)+MAG(TXYZ(5))");
  EXPECT_EQ(hostNames(f), (std::vector<std::string>{"WX", "WY", "WZ", "ACCX", "ACCY", "ACCZ",
                                                      "WDTX", "WDTY", "WDTZ", "FX", "FY", "FZ",
                                                      "TX", "TY", "TZ"}));
}

TEST(Vectors, DotProductScalingAndSums) {
  const Expression e = parseOk("DXYZ(1,2)*VXYZ(1,2)");
  const std::vector<double> h = {0.3, -1.2, 2.5, 0.7, 0.4, -0.9};
  EXPECT_DOUBLE_EQ(e.evaluate(h.data(), 0.0), 0.3 * 0.7 - 1.2 * 0.4 - 2.5 * 0.9);
  checkAllDerivatives(e, h, 0.0, "dot");
  // (2*d - v/4) * [1, TIME, 0] = (2 dx - vx/4) + TIME (2 dy - vy/4)
  const Expression s = parseOk("(2*DXYZ(1,2) - VXYZ(1,2)/4) * [1, TIME, 0]");
  EXPECT_DOUBLE_EQ(s.evaluate(h.data(), 1.5),
                   (2 * 0.3 - 0.7 / 4) + 1.5 * (2 * -1.2 - 0.4 / 4));
  checkAllDerivatives(s, h, 1.5, "scaled sum");
  EXPECT_DOUBLE_EQ(parseOk("-[1, 2, 3]*[4, 5, 6]").evaluate(nullptr, 0.0), -32.0);
  EXPECT_DOUBLE_EQ(parseOk("([1, 2, 3]*2)*[1, 0, 0]").evaluate(nullptr, 0.0), 2.0);
}

TEST(Vectors, CrossProductIsRightHanded) {
  // x % y = z, and |a % b| = |a||b| sin(angle) for a known pair.
  EXPECT_DOUBLE_EQ(parseOk("([1,0,0] % [0,1,0]) * [0,0,1]").evaluate(nullptr, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(parseOk("([0,1,0] % [1,0,0]) * [0,0,1]").evaluate(nullptr, 0.0), -1.0);
  const Expression e = parseOk("MAG(DXYZ(1) % [0, 0, 2])");
  const std::vector<double> h = {0.6, -0.8, 5.0};
  EXPECT_NEAR(e.evaluate(h.data(), 0.0), 2.0 * std::hypot(0.6, 0.8), 1e-15);
  checkAllDerivatives(e, h, 0.0, "cross");
  // Componentwise: a % b for a = (1,2,3), b = (4,5,6) is (-3, 6, -3).
  EXPECT_DOUBLE_EQ(parseOk("([1,2,3] % [4,5,6]) * [1,10,100]").evaluate(nullptr, 0.0),
                   -3.0 + 60.0 - 300.0);
}

TEST(Vectors, MagAndUnitVectorGiveTheSeparationVelocity) {
  // UV(DXYZ(i,j)) * VXYZ(i,j) is VR(i,j) = (d . v) / |d| (docs/expressions.md, "Vectors").
  const Expression e = parseOk("VXYZ(1,2)*UV(DXYZ(1,2))");
  const std::vector<double> h = {0.7, 0.4, -0.9, 0.3, -1.2, 2.5};  // VX VY VZ DX DY DZ
  const double d = std::sqrt(0.3 * 0.3 + 1.2 * 1.2 + 2.5 * 2.5);
  EXPECT_NEAR(e.evaluate(h.data(), 0.0), (0.7 * 0.3 - 0.4 * 1.2 - 0.9 * 2.5) / d, 1e-15);
  checkAllDerivatives(e, h, 0.0, "VR via UV");
  EXPECT_DOUBLE_EQ(parseOk("MAG([3, 4, 12])").evaluate(nullptr, 0.0), 13.0);
  EXPECT_DOUBLE_EQ(parseOk("MAG(UV([3, 4, 12]))").evaluate(nullptr, 0.0), 1.0);
}

TEST(UserCalls, ArgumentsAreKeptAsNumbers) {
  const Expression e = parseOk("USER(1.05, 2*PI, -3, 90D)");
  ASSERT_NE(e.userCall(), nullptr);
  EXPECT_EQ(e.userCall()->column, 1);
  ASSERT_EQ(e.userCall()->arguments.size(), 4u);
  EXPECT_DOUBLE_EQ(e.userCall()->arguments[0], 1.05);
  EXPECT_DOUBLE_EQ(e.userCall()->arguments[1], 2 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(e.userCall()->arguments[2], -3.0);
  EXPECT_DOUBLE_EQ(e.userCall()->arguments[3], std::numbers::pi / 2);
  EXPECT_TRUE(std::isnan(e.evaluate(nullptr, 0.0)));  // the subroutine supplies the value
  EXPECT_TRUE(parseOk("USER()").userCall()->arguments.empty());
  EXPECT_EQ(parseOk("TIME").userCall(), nullptr);
  // Copies keep the call.
  const Expression copy = e;
  ASSERT_NE(copy.userCall(), nullptr);
  EXPECT_EQ(copy.userCall()->arguments.size(), 4u);
}

}  // namespace
}  // namespace openmss::expr
