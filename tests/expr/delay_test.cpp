// DELAY (docs/expressions.md, "DELAY"): the history buffer's cubic interpolation against its
// error bound, the expression's value before and after TIME = start + delay against closed
// forms, zero and negative delays, the exact partials against central differences, and the
// input errors.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "expr/delay_history.hpp"
#include "expr/run_context.hpp"
#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::allMessages;
using testing::centralDifference;
using testing::parseOk;

// A run that recorded each DELAY argument of one expression at the given times.
class RecordedRun : public RunContext {
 public:
  const DelayHistory* delayHistory(const void* key) const override {
    const auto it = histories.find(key);
    return it == histories.end() || it->second.empty() ? nullptr : &it->second;
  }
  std::map<const void*, DelayHistory> histories;
};

// Irregular steps in [0, 3], as a variable-step integrator makes them.
std::vector<double> irregularTimes() {
  std::vector<double> t{0.0};
  double h = 0.01;
  while (t.back() < 3.0) {
    t.push_back(t.back() + h);
    h *= (t.size() % 3 == 0) ? 0.7 : 1.3;
    h = std::min(h, 0.08);
  }
  return t;
}

// Lagrange interpolation error: |f(s) - p(s)| <= max|f''''| / 4! * |prod (s - t_i)| over the
// four stencil points. For sin, max|f''''| = 1.
TEST(DelayHistory, CubicInterpolationStaysWithinItsErrorBound) {
  const std::vector<double> t = irregularTimes();
  DelayHistory h;
  for (double ti : t) h.record(ti, std::sin(ti));
  double worstRatio = 0.0;
  for (double s = 0.0; s <= t.back(); s += 0.00731) {
    // The stencil DelayHistory uses: two records each side, clamped at the ends.
    const auto upper = std::upper_bound(t.begin(), t.end(), s) - t.begin();
    const auto first =
        std::clamp<std::ptrdiff_t>(upper - 2, 0, static_cast<std::ptrdiff_t>(t.size()) - 4);
    double product = 1.0;
    for (int i = 0; i < 4; ++i) product *= s - t[static_cast<std::size_t>(first + i)];
    const double bound = std::abs(product) / 24.0 + 1e-15;
    const double error = std::abs(h.at(s).value - std::sin(s));
    EXPECT_LE(error, bound) << "s=" << s;
    worstRatio = std::max(worstRatio, error / bound);
    // The slope is the interpolant's own derivative.
    const double fd = centralDifference([&](double x) { return h.at(x).value; }, s, 1e-6);
    // Away from records the cubic is smooth; at a record the stencil may switch, so skip.
    bool nearRecord = false;
    for (double ti : t) nearRecord = nearRecord || std::abs(ti - s) < 1e-5;
    if (!nearRecord) {
      EXPECT_NEAR(h.at(s).slope, fd, 1e-7) << "s=" << s;
    }
  }
  EXPECT_GT(worstRatio, 0.01);  // the bound is tight enough to mean something
}

TEST(DelayHistory, RecordingAtAnEarlierTimeDropsTheLaterRecords) {
  DelayHistory h;
  for (double t : {0.0, 0.1, 0.2, 0.3}) h.record(t, t);
  h.record(0.15, 7.0);  // a restart at an event inside the last steps
  EXPECT_EQ(h.size(), 3u);
  EXPECT_DOUBLE_EQ(h.lastTime(), 0.15);
  EXPECT_DOUBLE_EQ(h.at(0.15).value, 7.0);
}

// DELAY(SIN(TIME), 0.5, 0): 0 before TIME = 0.5 (the history), sin(t - 0.5) after, to the
// interpolation bound of even steps h = 0.01 (fourth derivative at most 1): max|prod(s - t_i)|
// / 24 is 3 h^4 / 128 = 2.3e-10 inside and 15 h^4 / 384 = 3.9e-10 in the end intervals.
TEST(Delay, SineDelayedByHalfASecondFollowsTheClosedForm) {
  const Expression e = parseOk("DELAY(SIN(TIME), 0.5, 0)");
  ASSERT_EQ(e.delayCount(), 1u);
  RecordedRun run;
  DelayHistory& h = run.histories[e.delayKey(0)];
  const double step = 0.01;
  for (int k = 0; k <= 300; ++k) {
    const double t = k * step;
    // The run records e_delayed at accepted states.
    h.record(t, e.delayArgument(0, nullptr, t));
    const double want = t < 0.5 ? 0.0 : std::sin(t - 0.5);
    EXPECT_NEAR(e.evaluate(nullptr, t, &run), want, 3.9e-10) << "t=" << t;
  }
  // Without a run the history expression is read: DELAY(TIME, 1, TIME) is TIME - 1.
  EXPECT_DOUBLE_EQ(parseOk("DELAY(TIME, 1, TIME)").evaluate(nullptr, 0.25), -0.75);
}

// A zero or negative delay is the argument itself (ADAMS takes negative delays as zero), with
// the argument's derivative; a positive one has no derivative with respect to the current value
// of e_delayed, and d/d(delay) = -slope of the history.
TEST(Delay, PartialsMatchCentralDifferences) {
  const Expression e = parseOk("DELAY(3*VARVAL(1), VARVAL(2), 0)");
  ASSERT_EQ(e.hostCalls().size(), 2u);
  RecordedRun run;
  DelayHistory& h = run.histories[e.delayKey(0)];
  for (int k = 0; k <= 100; ++k) h.record(0.02 * k, std::cos(0.02 * k));
  const double time = 2.0;
  for (double delay : {0.0, -0.3, 0.37, 1.21}) {
    double host[2] = {0.4, delay};
    double dHost[2] = {0.0, 0.0};
    double dTime = 0.0;
    const double v = e.evaluate(host, time, dHost, &dTime, &run);
    EXPECT_DOUBLE_EQ(v, e.evaluate(host, time, &run));
    if (delay <= 0.0) {
      EXPECT_DOUBLE_EQ(v, 1.2);
      EXPECT_DOUBLE_EQ(dHost[0], 3.0);
      EXPECT_DOUBLE_EQ(dHost[1], 0.0);
      continue;
    }
    EXPECT_NEAR(v, std::cos(time - delay), 1e-8);
    EXPECT_EQ(dHost[0], 0.0);
    const auto at = [&](double d) {
      double x[2] = {0.4, d};
      return e.evaluate(x, time, &run);
    };
    EXPECT_NEAR(dHost[1], centralDifference(at, delay, 1e-5), 1e-7);
    const auto atTime = [&](double t) { return e.evaluate(host, t, &run); };
    EXPECT_NEAR(dTime, centralDifference(atTime, time, 1e-5), 1e-7);
  }
}

TEST(Delay, InputErrorsNameTheArgument) {
  struct Case {
    const char* text;
    const char* message;
  } cases[] = {
      {"DELAY(TIME, 1, 0, 5)", "names ARRAY/5 of interpolation options"},
      {"DELAY(DELAY(TIME, 1, 0), 1, 0)", "contains another DELAY"},
      {"DELAY(TIME, 1, DX(1))", "must be a function of TIME or a constant"},
      {"DELAY(TIME, 1)", "DELAY at column 1 of the expression has 2 arguments"},
  };
  for (const Case& c : cases) {
    Diagnostics diags;
    Expression e;
    EXPECT_FALSE(Expression::parse(c.text, {"m.adm", 3, 10}, "VARIABLE/1", diags, e)) << c.text;
    EXPECT_NE(allMessages(diags).find(c.message), std::string::npos) << c.text << "\n"
                                                                     << allMessages(diags);
  }
}

}  // namespace
}  // namespace openmss::expr
