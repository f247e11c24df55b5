#pragma once
// Helpers shared by the expression tests: parse-or-fail, evaluation shortcuts and central
// finite differences with Richardson extrapolation (error O(h^4)), used as the independent
// reference for every derivative.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "expr/expression.hpp"

namespace openmss::expr::testing {

inline std::string allMessages(const Diagnostics& diags) {
  std::string out;
  for (const Diagnostic& d : diags.all()) out += format(d) + "\n";
  return out;
}

inline Expression parseOk(const std::string& text) {
  Diagnostics diags;
  Expression e;
  const bool ok = Expression::parse(text, {"test.adm", 7, 20}, "VARIABLE/1", diags, e);
  EXPECT_TRUE(ok) << text << "\n" << allMessages(diags);
  return e;
}

// Value of a host-free expression at `time`.
inline double valueOf(const std::string& text, double time = 0.0) {
  return parseOk(text).evaluate(nullptr, time);
}

// d f / dx at x by central differences, Richardson-extrapolated from steps h and h/2.
inline double centralDifference(const std::function<double(double)>& f, double x, double h) {
  const auto d = [&](double step) { return (f(x + step) - f(x - step)) / (2.0 * step); };
  return (4.0 * d(0.5 * h) - d(h)) / 3.0;
}

// The step used throughout: 1e-4 relative to the point (absolute 1e-4 near zero), small
// enough that the O(h^4) truncation is far below 1e-6 relative and large enough that the
// rounding error (about 1e-16 / h) is too.
inline double stepFor(double x) { return 1e-4 * std::max(1.0, std::abs(x)); }

// Relative agreement to 1e-6, with an absolute floor of 1e-9 times the size of the function
// for derivatives that are zero or nearly so.
inline void expectDerivativeNear(double analytic, double numeric, double functionScale,
                                 const std::string& what) {
  const double tolerance =
      1e-6 * std::max(std::abs(analytic), std::abs(numeric)) + 1e-9 * std::max(1.0, functionScale);
  EXPECT_NEAR(analytic, numeric, tolerance) << what;
}

// Checks every host partial and the time partial of `e` at (hostValues, time) against
// finite differences.
inline void checkAllDerivatives(const Expression& e, std::vector<double> host, double time,
                                const std::string& what) {
  std::vector<double> dHost(host.size(), -999.0);
  double dTime = -999.0;
  const double value = e.evaluate(host.data(), time, dHost.data(), &dTime);
  EXPECT_DOUBLE_EQ(value, e.evaluate(host.data(), time)) << what;
  for (std::size_t k = 0; k < host.size(); ++k) {
    const auto f = [&](double x) {
      std::vector<double> moved = host;
      moved[k] = x;
      return e.evaluate(moved.data(), time);
    };
    expectDerivativeNear(dHost[k], centralDifference(f, host[k], stepFor(host[k])), std::abs(value),
                         what + " d/dhost" + std::to_string(k));
  }
  const auto g = [&](double t) { return e.evaluate(host.data(), t); };
  expectDerivativeNear(dTime, centralDifference(g, time, stepFor(time)), std::abs(value),
                       what + " d/dTIME");
}

}  // namespace openmss::expr::testing
