// AKISPL, CUBSPL and CURVE in expressions (data calls): parsing checks, binding, and exact
// derivatives. Reverse-mode partials with respect to host values and TIME are compared with
// central differences (Richardson, step 1e-4 relative; 1e-6 relative agreement, see
// expr_test_support.hpp) at points away from the knots, where the splines' second derivative
// jumps. Time jets of AKISPL(TIME, ...) and CURVE(f(TIME), ...) are compared with the spline's
// own derivatives (exact) and with differences of the first derivative.

#include <cmath>
#include <memory>

#include "common/bspline_curve.hpp"
#include "common/spline.hpp"
#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

using testing::allMessages;
using testing::checkAllDerivatives;
using testing::parseOk;

std::shared_ptr<const Spline> singleCurve() {
  const std::vector<double> x = {-1.0, 0.0, 0.7, 1.5, 2.0, 3.2, 4.0};
  const std::vector<double> y = {0.5, 0.0, 0.3, 1.4, 1.2, -0.6, 0.1};
  return std::make_shared<const Spline>(x, std::vector<double>{0.0},
                                        std::vector<std::vector<double>>{y}, false);
}

std::shared_ptr<const Spline> family() {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.5};
  return std::make_shared<const Spline>(
      x, std::vector<double>{-1.0, 0.5, 2.0},
      std::vector<std::vector<double>>{
          {0.0, 1.0, 0.5, 2.0, 1.0}, {1.0, 0.2, 0.4, 0.9, 3.0}, {2.0, 2.5, 1.0, 0.0, 0.5}},
      true);
}

void bindAll(Expression& e) {
  for (std::size_t k = 0; k < e.dataCalls().size(); ++k) {
    if (e.dataCalls()[k].name == "CURVE") {
      std::vector<std::array<double, 3>> points;
      for (int i = 0; i < 7; ++i) points.push_back({std::cos(i), 0.3 * i * i, 0.1 * i});
      e.bindCurve(k, std::make_shared<const BSplineCurve>(points, 4, false, true));
    } else {
      e.bindSpline(k, e.dataCalls()[k].id == 2 ? family() : singleCurve());
    }
  }
}

TEST(DataCalls, ParseRecordsIdsOrdersAndColumns) {
  Expression e =
      parseOk("1 + AKISPL(DM(1,2), 0, 5) * CUBSPL(TIME, VARVAL(3), 2, 1) + CURVE(TIME, 2, 3, 9)");
  ASSERT_EQ(e.dataCalls().size(), 3u);
  EXPECT_EQ(e.dataCalls()[0].name, "AKISPL");
  EXPECT_EQ(e.dataCalls()[0].id, 5);
  EXPECT_EQ(e.dataCalls()[0].order, 0);
  EXPECT_EQ(e.dataCalls()[0].column, 5);
  EXPECT_EQ(e.dataCalls()[1].id, 2);
  EXPECT_EQ(e.dataCalls()[1].order, 1);
  EXPECT_EQ(e.dataCalls()[2].name, "CURVE");
  EXPECT_EQ(e.dataCalls()[2].id, 9);
  EXPECT_EQ(e.dataCalls()[2].order, 2);
  EXPECT_EQ(e.dataCalls()[2].component, 3);
  EXPECT_EQ(e.hostCalls().size(), 2u);  // DM and VARVAL
  // Unbound: NaN, never a silent number.
  const double host[2] = {1.0, 0.0};
  EXPECT_TRUE(std::isnan(e.evaluate(host, 0.5)));
}

TEST(DataCalls, BadArgumentsAreReported) {
  const struct {
    const char* text;
    const char* message;
  } cases[] = {
      {"AKISPL(TIME, 0, 3, 5)",
       "test.adm:7:39: error: VARIABLE/1: AKISPL argument 4 at column 20 of the expression (iord) "
       "is 5, but it must "
       "be 0, 1 or 2. Write 0 for the value, 1 or 2 for the first or second derivative."},
      {"CUBSPL(TIME, 0, 1.5)",
       "test.adm:7:36: error: VARIABLE/1: CUBSPL argument 3 at column 17 of the expression is 1.5, "
       "not an integer. "
       "Arguments of CUBSPL are ids and flags: write integers, with 0 as the placeholder for an "
       "omitted one."},
      {"CURVE(TIME, 0, 4, 1)",
       "test.adm:7:35: error: VARIABLE/1: CURVE argument 3 at column 16 of the expression (comp) "
       "is 4, but it must "
       "be 1, 2 or 3. Write 1, 2 or 3 for the x, y or z component."},
      {"AKISPL(TIME, 0)",
       "test.adm:7:20: error: VARIABLE/1: AKISPL at column 1 of the expression has 2 arguments, "
       "but AKISPL takes 3 "
       "to 4. Write AKISPL(x, z, id[, iord])."},
      {"INTERP(TIME, 1)",
       "test.adm:7:20: error: VARIABLE/1: INTERP at column 1 of the expression has 2 arguments, "
       "but INTERP takes 3 to 4. Write INTERP(x, degree, id[, iord])."},
  };
  for (const auto& c : cases) {
    Diagnostics diags;
    Expression e;
    EXPECT_FALSE(Expression::parse(c.text, {"test.adm", 7, 20}, "VARIABLE/1", diags, e)) << c.text;
    EXPECT_EQ(allMessages(diags), std::string(c.message) + "\n");
  }
}

TEST(DataCalls, PartialsMatchCentralDifferences) {
  // Hosts: h0 = x-like measure, h1 = z-like measure. Points avoid the knots (x = 0, 0.7, 1.5,
  // 2 ...; z curves at -1, 0.5, 2) so that the central differences do not straddle a jump of
  // the second derivative.
  const char* texts[] = {
      "AKISPL(DM(1,2), 0, 1)",
      "CUBSPL(DM(1,2), 0, 1)",
      "AKISPL(DM(1,2), 0, 1, 1)",
      "CUBSPL(DM(1,2)**2 - 1, 0, 1, 2) * TIME",
      "3*CUBSPL(DM(1,2), VARVAL(4), 2) + AKISPL(TIME, VARVAL(4), 2, 1)",
      "AKISPL(DM(1,2), VARVAL(4), 2, 2) + CUBSPL(2*DM(1,2), VARVAL(4)**2, 2, 1)",
      "CURVE(0.4*DM(1,2) - 0.6, 0, 2, 7) + CURVE(TIME/10, 1, 1, 7)",
      "CUBSPL(DM(1,2), 0, 1) * CUBSPL(VARVAL(4), 0, 1)",
  };
  for (const char* text : texts) {
    Expression e = parseOk(text);
    bindAll(e);
    for (const auto& point : {std::vector<double>{0.35, -0.3}, std::vector<double>{1.1, 1.2},
                              std::vector<double>{2.6, 1.7}, std::vector<double>{-1.6, 2.9}}) {
      std::vector<double> host(e.hostCalls().size());
      for (std::size_t k = 0; k < host.size(); ++k) host[k] = point[k];
      checkAllDerivatives(e, host, 0.83, text);
    }
  }
}

TEST(DataCalls, TimeJetsCarryTheSplineDerivatives) {
  const std::shared_ptr<const Spline> s = singleCurve();
  for (SplineMethod method : {SplineMethod::Akima, SplineMethod::Cubic}) {
    Expression e =
        parseOk(method == SplineMethod::Akima ? "AKISPL(TIME, 0, 1)" : "CUBSPL(TIME, 0, 1)");
    e.bindSpline(0, s);
    for (double t : {-2.0, 0.2, 1.1, 3.9, 5.0}) {
      double d[5];
      s->curveDerivatives(method, 0, t, d);
      const TimeJet jet = e.evaluateTimeJet(t);
      EXPECT_DOUBLE_EQ(jet.value, d[0]);
      EXPECT_DOUBLE_EQ(jet.d1, d[1]);
      EXPECT_DOUBLE_EQ(jet.d2, d[2]);
    }
  }
  // Chain rule with an inner function of TIME and a z that varies with TIME too:
  // g(x(t), z(t)) with x = t^2, z = sin t. d2g/dt2 is checked against differences of d1.
  Expression e = parseOk("CUBSPL(TIME**2, SIN(TIME), 2, 1) + CURVE(0.3*TIME - 0.5, 1, 2, 4)");
  bindAll(e);
  for (double t : {0.45, 1.25, 1.9}) {
    const TimeJet jet = e.evaluateTimeJet(t);
    const double h = testing::stepFor(t);
    const auto value = [&](double x) { return e.evaluateTimeJet(x).value; };
    const auto slope = [&](double x) { return e.evaluateTimeJet(x).d1; };
    testing::expectDerivativeNear(jet.d1, testing::centralDifference(value, t, h),
                                  std::abs(jet.value), "d1");
    testing::expectDerivativeNear(jet.d2, testing::centralDifference(slope, t, h), std::abs(jet.d1),
                                  "d2");
  }
}

TEST(DataCalls, CopiesShareTheBoundData) {
  Expression e = parseOk("AKISPL(TIME, 0, 1)");
  e.bindSpline(0, singleCurve());
  const Expression copy = e;
  e = Expression();
  EXPECT_DOUBLE_EQ(copy.evaluate(nullptr, 0.7), 0.3);  // a knot value
}

}  // namespace
}  // namespace openmss::expr
