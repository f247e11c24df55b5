// Expression::evaluateJet (host values given as second-order jets along a path parameter s):
// the jet's first and second derivatives against central differences of the plain value along
// the same path, h_k(s) = h_k + s h_k' + s^2/2 h_k'', for expressions mixing host calls with
// the library (powers, ATAN2, IF, STEP, division). GCON equations depend on it (theory §5c).

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

TEST(HostJet, MatchesDifferencesOfTheValueAlongThePath) {
  const std::string texts[] = {
      "DX(1,2)**2+DY(1,2)**2-4",
      "SIN(AZ(3,4))*DM(5,6)**3/(1+DX(1,2)**2)",
      "ATAN2(DY(1,2),DX(1,2))+STEP(DM(5,6),-5,0,5,2)*EXP(0.3*AZ(3,4))",
      "IF(DX(1,2)-10:SQRT(DM(5,6)**2+1)*COS(AZ(3,4)),0,1)+DY(1,2)**-2",
  };
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const std::string& text : texts) {
    const Expression e = testing::parseOk(text);
    const size_t n = e.hostCalls().size();
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<TimeJet> jets(n);
      for (auto& j : jets) j = {1.5 + 0.5 * u(rng), u(rng), u(rng)};
      auto along = [&](double s) {
        std::vector<double> h(n);
        for (size_t k = 0; k < n; ++k)
          h[k] = jets[k].value + s * jets[k].d1 + 0.5 * s * s * jets[k].d2;
        return e.evaluate(h.data(), 0.0);
      };
      const TimeJet j = e.evaluateJet(jets.data(), 0.0);
      EXPECT_DOUBLE_EQ(j.value, along(0.0)) << text;
      const double d1 = testing::centralDifference(along, 0.0, 1e-3);
      const double hh = 1e-3;
      const double d2 = (along(hh) - 2.0 * along(0.0) + along(-hh)) / (hh * hh);
      const double d2b = (along(hh / 2) - 2.0 * along(0.0) + along(-hh / 2)) / (hh * hh / 4);
      const double d2r = (4.0 * d2b - d2) / 3.0;  // Richardson: error O(h^4)
      EXPECT_NEAR(j.d1, d1, 1e-6 * (1.0 + std::abs(d1))) << text;
      EXPECT_NEAR(j.d2, d2r, 1e-6 * (1.0 + std::abs(d2r))) << text;
    }
  }
}

}  // namespace
}  // namespace openmss::expr
