// CURVE geometry (src/common/bspline_curve.cpp) against closed forms:
//  * CURVE_POINTS, ORDER=4, open: points sampled at even alpha from a cubic in alpha are
//    reproduced exactly (the spline space holds all cubics and interpolation is unique), with
//    the derivatives in alpha, to 1e-10;
//  * ORDER=2 is the polygon through the points (CURVE_POINTS) or control points;
//  * control-point curves are clamped: they start and end at the first and last control point
//    and leave along the first and last leg;
//  * CLOSED curves pass through their points and are periodic with continuous value, first and
//    (order >= 4) second derivative across alpha = +-1 (1e-9);
//  * derivatives agree with central differences of the value (1e-6 relative).

#include "common/bspline_curve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace openmss {
namespace {

using Points = std::vector<std::array<double, 3>>;

std::array<double, 3> cubicAt(double a) {
  return {1.0 + 2.0 * a - a * a * a, 0.5 * a * a - a, 3.0 - 0.25 * a * a * a + a * a};
}

TEST(BSplineCurve, InterpolatingCubicReproducesCubicPolynomials) {
  Points points;
  const int m = 9;
  for (int i = 0; i < m; ++i) points.push_back(cubicAt(-1.0 + 2.0 * i / (m - 1)));
  ASSERT_EQ(BSplineCurve::check(points, 4, false), "");
  const BSplineCurve c(points, 4, false, true);
  for (double a = -1.0; a <= 1.0; a += 0.0173) {
    const double h = 1e-6;
    for (int comp = 0; comp < 3; ++comp) {
      double d[5];
      c.derivatives(a, comp, d);
      EXPECT_NEAR(d[0], cubicAt(a)[comp], 1e-12) << a << " " << comp;
      const double slope = (cubicAt(a + h)[comp] - cubicAt(a - h)[comp]) / (2 * h);
      EXPECT_NEAR(d[1], slope, 1e-8) << a << " " << comp;
    }
    double d[5];
    c.derivatives(a, 0, d);
    EXPECT_NEAR(d[2], -6.0 * a, 1e-9);
    EXPECT_NEAR(d[3], -6.0, 1e-8);
  }
}

TEST(BSplineCurve, OrderTwoIsThePolygon) {
  const Points points = {{0, 0, 0}, {450, -50, 0}, {850, -50, 0}, {1300, 0, 0}};
  for (bool through : {true, false}) {
    const BSplineCurve c(points, 2, false, through);
    double d[5];
    // Uniform parameters: point i at alpha = -1 + 2 i / 3; midway along the second leg.
    c.derivatives(0.0, 0, d);
    EXPECT_NEAR(d[0], 650.0, 1e-12);
    EXPECT_NEAR(d[1], 400.0 * 1.5, 1e-10);  // 400 per third of the parameter range of 2
    EXPECT_EQ(d[2], 0.0);
    c.derivatives(1.0, 0, d);
    EXPECT_NEAR(d[0], 1300.0, 1e-12);
    c.derivatives(-1.0 + 2.0 / 3.0, 1, d);
    EXPECT_NEAR(d[0], -50.0, 1e-12);
  }
}

TEST(BSplineCurve, ControlPointCurveIsClamped) {
  const Points control = {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 1, 0}, {6, 0, 2}};
  const BSplineCurve c(control, 4, false, false);
  double x[5], y[5];
  c.derivatives(-1.0, 0, x);
  c.derivatives(-1.0, 1, y);
  EXPECT_NEAR(x[0], 0.0, 1e-14);
  EXPECT_NEAR(y[0], 0.0, 1e-14);
  EXPECT_NEAR(y[1] / x[1], 2.0, 1e-12);  // along P1 - P0
  c.derivatives(1.0, 0, x);
  c.derivatives(1.0, 1, y);
  EXPECT_NEAR(x[0], 6.0, 1e-14);
  EXPECT_NEAR(y[0], 0.0, 1e-14);
  EXPECT_NEAR(y[1] / x[1], -0.5, 1e-12);  // along P4 - P3
}

TEST(BSplineCurve, ClosedCurvesArePeriodicAndSmooth) {
  Points circle;
  const int n = 12;
  for (int i = 0; i <= n; ++i) {
    const double phi = 2.0 * std::numbers::pi * (i % n) / n;
    circle.push_back({std::cos(phi), std::sin(phi), 0.0});
  }
  for (int order : {3, 4, 5}) {
    ASSERT_EQ(BSplineCurve::check(circle, order, true), "");
    for (bool through : {true, false}) {
      const BSplineCurve c(circle, order, true, through);
      for (int comp = 0; comp < 2; ++comp) {
        double before[5], after[5];
        c.derivatives(1.0 - 1e-12, comp, before);
        c.derivatives(-1.0, comp, after);
        // An order-k B-spline is C(k-2) at its knots, and the closure is at a knot.
        for (int k = 0; k < std::min(3, order - 1); ++k) {
          EXPECT_NEAR(before[k], after[k], 1e-9 * std::pow(2.0 * n, k))
              << order << through << comp << k;
        }
        double shifted[5];
        c.derivatives(0.3 + 2.0, comp, after);
        c.derivatives(0.3, comp, shifted);
        EXPECT_NEAR(after[0], shifted[0], 1e-13);
      }
      if (through && order % 2 == 0) {
        // Even order: the sites are the points' parameters -1 + 2 i / n.
        for (int i = 0; i < n; ++i) {
          double x[5];
          c.derivatives(-1.0 + 2.0 * i / n, 0, x);
          EXPECT_NEAR(x[0], circle[i][0], 1e-12) << i;
        }
      }
    }
  }
  EXPECT_NE(BSplineCurve::check({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 4, true), "");
}

TEST(BSplineCurve, DerivativesMatchCentralDifferences) {
  const Points points = {{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 1, 0}, {6, 0, 2}, {7, 2, 2}};
  for (bool closedCurve : {false}) {
    for (int order : {3, 4, 5}) {
      const BSplineCurve c(points, order, closedCurve, true);
      for (double a : {-0.83, -0.21, 0.37, 0.71}) {
        for (int comp = 0; comp < 3; ++comp) {
          const double h = 1e-5;
          double d[5], plus[5], minus[5];
          c.derivatives(a, comp, d);
          c.derivatives(a + h, comp, plus);
          c.derivatives(a - h, comp, minus);
          for (int k = 0; k < 3; ++k) {
            const double numeric = (plus[k] - minus[k]) / (2 * h);
            EXPECT_NEAR(d[k + 1], numeric, 1e-6 * std::max(1.0, std::abs(numeric)))
                << order << " " << a << " " << comp << " " << k;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace openmss
