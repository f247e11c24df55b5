// SPLINE interpolation (src/common/spline.cpp) against closed forms:
//  * CUBSPL (not-a-knot) reproduces any cubic exactly, on uneven spacing too: value and the
//    first three derivatives to 1e-10 relative (the tridiagonal solve is the only error);
//  * AKISPL reproduces straight lines on any spacing and parabolas on even spacing (the
//    weights are then equal and the slope is the mean of two secants, exact for a parabola);
//  * value and slope are continuous at every knot for both, the second derivative for CUBSPL
//    (left and right limits from the two polynomial pieces agree to 1e-12 relative);
//  * extrapolation is the parabola through the three end points, or the line through two;
//  * a family is linear in z, with the exact z partials.

#include "common/spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace openmss {
namespace {

double cubic(double x) { return 2.0 - x + 0.5 * x * x - 0.3 * x * x * x; }
double cubic1(double x) { return -1.0 + x - 0.9 * x * x; }
double cubic2(double x) { return 1.0 - 1.8 * x; }

std::vector<double> sample(const std::vector<double>& x, double (*f)(double)) {
  std::vector<double> y;
  for (double v : x) y.push_back(f(v));
  return y;
}

const std::vector<double> kUneven = {-2.0, -1.3, -0.2, 0.1, 0.9, 2.5, 3.0, 4.2};

TEST(Spline, CubicSplineReproducesCubicsOnUnevenKnots) {
  const Spline s(kUneven, {0.0}, {sample(kUneven, cubic)}, false);
  for (double x = -2.0; x <= 4.2; x += 0.0137) {
    double d[5];
    s.curveDerivatives(SplineMethod::Cubic, 0, x, d);
    EXPECT_NEAR(d[0], cubic(x), 1e-10 * 20.0) << x;
    EXPECT_NEAR(d[1], cubic1(x), 1e-10 * 20.0) << x;
    EXPECT_NEAR(d[2], cubic2(x), 1e-10 * 10.0) << x;
    EXPECT_NEAR(d[3], -1.8, 1e-9) << x;
  }
  // The same holds with just four points (one cubic through them).
  const std::vector<double> four = {0.0, 0.3, 1.1, 2.0};
  const Spline s4(four, {0.0}, {sample(four, cubic)}, false);
  for (double x = 0.0; x <= 2.0; x += 0.05) {
    EXPECT_NEAR(s4.evaluate(SplineMethod::Cubic, x, 0.0, 0).g, cubic(x), 1e-12) << x;
  }
}

TEST(Spline, AkimaReproducesLinesAndEvenlySpacedParabolas) {
  const Spline line(kUneven, {0.0}, {sample(kUneven, [](double x) { return 3.0 - 2.0 * x; })},
                    false);
  for (double x = -2.0; x <= 4.2; x += 0.031) {
    const SplinePartials p = line.evaluate(SplineMethod::Akima, x, 0.0, 0);
    EXPECT_NEAR(p.g, 3.0 - 2.0 * x, 1e-13) << x;
    EXPECT_NEAR(p.gx, -2.0, 1e-13) << x;
    EXPECT_NEAR(p.gxx, 0.0, 1e-12) << x;
  }
  std::vector<double> even;
  for (int i = 0; i < 9; ++i) even.push_back(-1.0 + 0.5 * i);
  const auto parabola = [](double x) { return 1.0 + 0.5 * x - 0.75 * x * x; };
  const Spline s(even, {0.0}, {sample(even, parabola)}, false);
  for (double x = -1.0; x <= 3.0; x += 0.023) {
    const SplinePartials p = s.evaluate(SplineMethod::Akima, x, 0.0, 0);
    EXPECT_NEAR(p.g, parabola(x), 1e-13) << x;
    EXPECT_NEAR(p.gx, 0.5 - 1.5 * x, 1e-12) << x;
    EXPECT_NEAR(p.gxx, -1.5, 1e-11) << x;
  }
}

TEST(Spline, ValueAndSlopeAreContinuousAtKnots) {
  // Data with corners (Akima's case) on uneven knots.
  const std::vector<double> y = {0.0, 0.2, 1.5, 1.4, 0.3, 0.3, 2.0, 2.2};
  const Spline s(kUneven, {0.0}, {y}, false);
  for (SplineMethod method : {SplineMethod::Akima, SplineMethod::Cubic}) {
    for (std::size_t i = 1; i + 1 < kUneven.size(); ++i) {
      // Limits from the left piece (at x_i - 1e-12 the left piece is used) are compared with
      // the right piece at x_i; the distance contributes at most ~1e-11.
      const double x = kUneven[i];
      double left[5], right[5];
      s.curveDerivatives(method, 0, std::nextafter(x, -1e9) - 1e-12, left);
      s.curveDerivatives(method, 0, x, right);
      EXPECT_NEAR(left[0], right[0], 1e-10) << i;
      EXPECT_NEAR(left[1], right[1], 1e-9) << i;
      if (method == SplineMethod::Cubic) {
        EXPECT_NEAR(left[2], right[2], 1e-8) << i;
      }
      // The knot values are interpolated.
      EXPECT_NEAR(right[0], y[i], 1e-14) << i;
    }
  }
}

TEST(Spline, AkimaIsLocal) {
  // Moving y_k changes Akima slopes k-2..k+2 only, so pieces two intervals away keep their
  // values; the global cubic spline changes everywhere.
  std::vector<double> x, y;
  for (int i = 0; i < 12; ++i) {
    x.push_back(i);
    y.push_back(std::sin(0.7 * i));
  }
  std::vector<double> moved = y;
  moved[8] += 1.0;
  const Spline a(x, {0.0}, {y}, false), b(x, {0.0}, {moved}, false);
  for (double t = 0.0; t <= 5.0; t += 0.1) {
    EXPECT_EQ(a.evaluate(SplineMethod::Akima, t, 0, 0).g,
              b.evaluate(SplineMethod::Akima, t, 0, 0).g);
  }
  EXPECT_NE(a.evaluate(SplineMethod::Cubic, 2.5, 0, 0).g,
            b.evaluate(SplineMethod::Cubic, 2.5, 0, 0).g);
}

TEST(Spline, ExtrapolatesWithEndParabolaOrEndLine) {
  const std::vector<double> x = {0.0, 1.0, 3.0, 4.0, 6.0};
  const std::vector<double> y = {1.0, 2.0, 0.5, -1.0, 2.0};
  // Lagrange parabola through three points.
  const auto lagrange = [](double t, double x0, double y0, double x1, double y1, double x2,
                           double y2) {
    return y0 * (t - x1) * (t - x2) / ((x0 - x1) * (x0 - x2)) +
           y1 * (t - x0) * (t - x2) / ((x1 - x0) * (x1 - x2)) +
           y2 * (t - x0) * (t - x1) / ((x2 - x0) * (x2 - x1));
  };
  const Spline parabolic(x, {0.0}, {y}, false);
  const Spline linear(x, {0.0}, {y}, true);
  for (SplineMethod m : {SplineMethod::Akima, SplineMethod::Cubic}) {
    for (double t : {-2.0, -0.5, -1e-3}) {
      EXPECT_NEAR(parabolic.evaluate(m, t, 0, 0).g, lagrange(t, 0, 1, 1, 2, 3, 0.5), 1e-13);
      EXPECT_NEAR(linear.evaluate(m, t, 0, 0).g, 1.0 + t, 1e-13);
      EXPECT_NEAR(linear.evaluate(m, t, 0, 1).g, 1.0, 1e-13);
      EXPECT_EQ(linear.evaluate(m, t, 0, 2).g, 0.0);
    }
    for (double t : {6.001, 7.0, 10.0}) {
      EXPECT_NEAR(parabolic.evaluate(m, t, 0, 0).g, lagrange(t, 3, 0.5, 4, -1, 6, 2), 1e-12);
      EXPECT_NEAR(linear.evaluate(m, t, 0, 0).g, 2.0 + 1.5 * (t - 6.0), 1e-13);
    }
    // Both meet the data at the end points.
    EXPECT_NEAR(parabolic.evaluate(m, std::nextafter(6.0, 7.0), 0, 0).g, 2.0, 1e-13);
  }
}

TEST(Spline, FamilyIsLinearInZ) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> y1 = {0.0, 1.0, 4.0, 9.0, 16.0};
  const std::vector<double> y2 = {1.0, 2.0, 1.0, 2.0, 1.0};
  const std::vector<double> y3 = {5.0, 5.0, 5.0, 5.0, 5.0};
  const Spline s(x, {10.0, 20.0, 40.0}, {y1, y2, y3}, false);
  const Spline c1(x, {0.0}, {y1}, false), c2(x, {0.0}, {y2}, false), c3(x, {0.0}, {y3}, false);
  for (SplineMethod m : {SplineMethod::Akima, SplineMethod::Cubic}) {
    for (int order = 0; order <= 2; ++order) {
      for (double t : {0.3, 1.7, 3.9}) {
        const double f1 = c1.evaluate(m, t, 0, order).g;
        const double f2 = c2.evaluate(m, t, 0, order).g;
        const double f3 = c3.evaluate(m, t, 0, order).g;
        const SplinePartials mid = s.evaluate(m, t, 12.5, order);
        EXPECT_NEAR(mid.g, 0.75 * f1 + 0.25 * f2, 1e-13);
        EXPECT_NEAR(mid.gz, (f2 - f1) / 10.0, 1e-14);
        EXPECT_NEAR(mid.gx,
                    0.75 * c1.evaluate(m, t, 0, order).gx + 0.25 * c2.evaluate(m, t, 0, order).gx,
                    1e-12);
        EXPECT_NEAR(mid.gxz,
                    (c2.evaluate(m, t, 0, order).gx - c1.evaluate(m, t, 0, order).gx) / 10.0,
                    1e-13);
        EXPECT_NEAR(s.evaluate(m, t, 30.0, order).g, 0.5 * (f2 + f3), 1e-13);
        // Exactly on a curve, and beyond the last one by linear extrapolation.
        EXPECT_NEAR(s.evaluate(m, t, 20.0, order).g, f2, 1e-13);
        EXPECT_NEAR(s.evaluate(m, t, 60.0, order).g, f3 + (f3 - f2), 1e-12);
        EXPECT_NEAR(s.evaluate(m, t, 0.0, order).g, f1 - (f2 - f1), 1e-12);
      }
    }
  }
}

}  // namespace
}  // namespace openmss
