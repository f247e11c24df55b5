// INTERP (time-series SPLINE, linear or cubic) and INVPSD (signal regenerated from a PSD).
// INTERP degree 1 is compared with the straight line through the data (closed form), degree 3
// with CUBSPL on the same data (the same not-a-knot spline). INVPSD is checked against its
// defining sum (frequencies, amplitudes from the PSD, the documented SplitMix64 phases), its
// mean square against the PSD integral (Parseval: exact for a trigonometric polynomial sampled
// uniformly over a whole period), determinism of the seed, and its derivatives against central
// differences (expr_test_support.hpp).

#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>

#include "common/spline.hpp"
#include "expr/data_functions.hpp"
#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::centralDifference;
using testing::parseOk;

const std::vector<double> kTimes = {0.0, 0.5, 1.25, 2.0, 3.0};
const std::vector<double> kValues = {1.0, 2.0, 0.5, -1.0, 4.0};

std::shared_ptr<const Spline> series() {
  return std::make_shared<const Spline>(kTimes, std::vector<double>{0.0},
                                        std::vector<std::vector<double>>{kValues}, false);
}

Expression bound(const std::string& text, std::shared_ptr<const Spline> spline) {
  Expression e = parseOk(text);
  for (std::size_t k = 0; k < e.dataCalls().size(); ++k) e.bindSpline(k, spline);
  return e;
}

TEST(Interp, ParsesDegreeIdAndOrder) {
  const Expression e = parseOk("INTERP(TIME, 3, 7, 2)");
  ASSERT_EQ(e.dataCalls().size(), 1u);
  EXPECT_EQ(e.dataCalls()[0].name, "INTERP");
  EXPECT_EQ(e.dataCalls()[0].id, 7);
  EXPECT_EQ(e.dataCalls()[0].order, 2);
  EXPECT_EQ(e.dataCalls()[0].parameters, (std::vector<double>{3.0}));
}

TEST(Interp, LinearIsTheStraightLineThroughTheData) {
  const Expression value = bound("INTERP(TIME, 1, 1)", series());
  const Expression slope = bound("INTERP(TIME, 1, 1, 1)", series());
  const Expression curvature = bound("INTERP(TIME, 1, 1, 2)", series());
  for (std::size_t k = 0; k + 1 < kTimes.size(); ++k) {
    const double m = (kValues[k + 1] - kValues[k]) / (kTimes[k + 1] - kTimes[k]);
    for (double s : {0.0, 0.3, 0.9}) {
      const double t = kTimes[k] + s * (kTimes[k + 1] - kTimes[k]);
      EXPECT_NEAR(value.evaluate(nullptr, t), kValues[k] + m * (t - kTimes[k]), 1e-12) << t;
      EXPECT_NEAR(slope.evaluate(nullptr, t), m, 1e-12) << t;  // at a knot: the right segment
      EXPECT_EQ(curvature.evaluate(nullptr, t), 0.0);
    }
  }
  // Beyond the ends the end segments continue.
  EXPECT_NEAR(value.evaluate(nullptr, -1.0), 1.0 - 2.0 * 1.0, 1e-12);
  EXPECT_NEAR(value.evaluate(nullptr, 4.0), 4.0 + 5.0 * 1.0, 1e-12);
  // Time jet inside a segment: slope and zero curvature.
  const TimeJet j = value.evaluateTimeJet(0.8);
  EXPECT_NEAR(j.d1, (0.5 - 2.0) / 0.75, 1e-12);
  EXPECT_EQ(j.d2, 0.0);
  double dTime = 0.0;
  value.evaluate(nullptr, 2.4, nullptr, &dTime);
  EXPECT_NEAR(dTime, 5.0, 1e-12);
}

TEST(Interp, CubicIsCubsplOfTheSameData) {
  for (int order = 0; order <= 2; ++order) {
    const std::string o = std::to_string(order);
    const Expression interp = bound("INTERP(TIME, 3, 1, " + o + ")", series());
    const Expression cubspl = bound("CUBSPL(TIME, 0, 1, " + o + ")", series());
    for (double t : {-0.5, 0.1, 0.7, 1.9, 2.6, 3.4}) {
      EXPECT_DOUBLE_EQ(interp.evaluate(nullptr, t), cubspl.evaluate(nullptr, t)) << t;
    }
  }
  const Expression e = bound("INTERP(TIME, 3, 1)", series());
  const auto f = [&](double t) { return e.evaluate(nullptr, t); };
  double dTime = 0.0;
  e.evaluate(nullptr, 1.6, nullptr, &dTime);
  testing::expectDerivativeNear(dTime, centralDifference(f, 1.6, 1e-4), 1.0, "cubic d/dt");
}

// A flat PSD of density P between 0 and 100 Hz.
std::shared_ptr<const Spline> flatPsd(double p) {
  return std::make_shared<const Spline>(
      std::vector<double>{0.0, 10.0, 50.0, 100.0}, std::vector<double>{0.0},
      std::vector<std::vector<double>>{{p, p, p, p}}, false);
}

TEST(InvPsd, IsTheDocumentedSumOfSines) {
  const Expression e = bound("INVPSD(TIME, 3, 1, 10, 10, 0, 42)", flatPsd(0.02));
  ASSERT_EQ(e.dataCalls()[0].parameters, (std::vector<double>{1, 10, 10, 0, 42}));
  // Frequencies 1..10 Hz (df = 1), amplitudes sqrt(2 P df), phases 2 pi u from SplitMix64(42).
  std::uint64_t state = 42;
  std::vector<double> phase;
  for (int i = 0; i < 10; ++i) phase.push_back(2.0 * std::numbers::pi * PsdSignal::uniform(state));
  for (double t : {0.0, 0.013, 0.37, 1.9}) {
    double expected = 0.0;
    for (int i = 0; i < 10; ++i) {
      expected += std::sqrt(2.0 * 0.02) * std::sin(2.0 * std::numbers::pi * (i + 1) * t + phase[i]);
    }
    EXPECT_NEAR(e.evaluate(nullptr, t), expected, 1e-12) << t;
  }
  // SplitMix64's published first output for seed 0 (Vigna's reference implementation).
  std::uint64_t zero = 0;
  EXPECT_DOUBLE_EQ(PsdSignal::uniform(zero),
                   static_cast<double>(0xE220A8397B1DCDAFULL >> 11) * 0x1.0p-53);
}

TEST(InvPsd, MeanSquareEqualsThePsdIntegral) {
  // Integer frequencies 1..10 Hz: the signal has period 1 s, and sampling N > 20 points
  // uniformly over it gives the mean square exactly: sum A_i^2 / 2 = nf P df.
  const double p = 0.02;
  const Expression e = bound("INVPSD(TIME, 3, 1, 10, 10, 0, 7)", flatPsd(p));
  const int n = 64;
  double meanSquare = 0.0;
  for (int k = 0; k < n; ++k) {
    const double v = e.evaluate(nullptr, static_cast<double>(k) / n);
    meanSquare += v * v / n;
  }
  EXPECT_NEAR(meanSquare, 10.0 * p * 1.0, 1e-12);
}

TEST(InvPsd, SeedsAreDeterministicAndDistinct) {
  const Expression a = bound("INVPSD(TIME, 3, 1, 10, 10, 0, 5)", flatPsd(1.0));
  const Expression b = bound("INVPSD(TIME, 3, 1, 10, 10, 0, 5.7)", flatPsd(1.0));  // int(5.7)
  const Expression c = bound("INVPSD(TIME, 3, 1, 10, 10, 0, 6)", flatPsd(1.0));
  EXPECT_EQ(a.evaluate(nullptr, 0.3), b.evaluate(nullptr, 0.3));
  EXPECT_NE(a.evaluate(nullptr, 0.3), c.evaluate(nullptr, 0.3));
}

TEST(InvPsd, LogarithmicReadingOfThePsd) {
  // S = f^-2 at the knots: log-log interpolation is exact for a power law, linear is not.
  const std::vector<double> f = {1.0, 2.0, 4.0, 8.0};
  std::vector<double> s;
  for (double x : f) s.push_back(1.0 / (x * x));
  EXPECT_NEAR(PsdSignal::psdAt(f, s, 3.0, true), 1.0 / 9.0, 1e-15);
  EXPECT_NEAR(PsdSignal::psdAt(f, s, 3.0, false), 0.25 + 0.5 * (1.0 / 16.0 - 0.25), 1e-15);
  EXPECT_EQ(PsdSignal::psdAt(f, s, 0.5, true), 1.0);    // held below the first knot
  EXPECT_EQ(PsdSignal::psdAt(f, s, 9.0, true), s.back());  // and above the last
}

TEST(InvPsd, DerivativesMatchFiniteDifferences) {
  const Expression e = bound("INVPSD(2*TIME + DX(1), 3, 0.5, 7, 12, 1, 3)", flatPsd(0.3));
  for (double t : {0.11, 0.73}) {
    const std::vector<double> host = {0.05};
    testing::checkAllDerivatives(e, host, t, "INVPSD");
  }
  const Expression m = bound("INVPSD(TIME, 3, 0.5, 7, 12, 1, 3)", flatPsd(0.3));
  const TimeJet j = m.evaluateTimeJet(0.4);
  const auto d1 = [&](double t) { return m.evaluateTimeJet(t).d1; };
  testing::expectDerivativeNear(j.d2, centralDifference(d1, 0.4, 1e-4), std::abs(j.d1), "d2");
}

}  // namespace
}  // namespace openmss::expr
