#pragma once
// Interpolation of tabulated SPLINE data: the AKISPL (Akima) and CUBSPL (cubic spline) methods,
// for one curve y(x) or a family of curves y(x, z) that is interpolated linearly in z
// (docs/theory.md, "Interpolation of SPLINE and CURVE data").
//
// It lives in common because both the model (which builds and checks the data) and the
// expression evaluator (which calls it in the inner loop) need it, and expr may not depend on
// model. A Spline is immutable after construction; evaluation is a binary search, a few
// multiply-adds and no allocation, so any number of threads may evaluate one Spline at once.

#include <cstddef>
#include <vector>

namespace openmss {

enum class SplineMethod { Akima, Cubic };

// g = d^order y / dx^order at (x, z), and its partial derivatives in x and z up to second
// order (gzz is zero: y is linear in z between two curves of a family).
struct SplinePartials {
  double g = 0.0, gx = 0.0, gz = 0.0, gxx = 0.0, gxz = 0.0, gzz = 0.0;
};

class Spline {
 public:
  // Preconditions (checked with diagnostics by the model builder): x strictly increasing with
  // at least 4 values; z strictly increasing with one entry per curve (any single value for one
  // curve); every curve has x.size() values.
  Spline(std::vector<double> x, std::vector<double> z,
         const std::vector<std::vector<double>>& curves, bool linearExtrapolation);

  // order 0, 1 or 2: the value, or the first or second derivative in x (AKISPL/CUBSPL iord).
  SplinePartials evaluate(SplineMethod method, double x, double z, int order) const;

  // d^k y_c / dx^k for k = 0..4 of curve c (the derivatives that exist: a cubic piece has none
  // beyond the third, an extrapolating parabola none beyond the second).
  void curveDerivatives(SplineMethod method, std::size_t curve, double x, double out[5]) const;

  std::size_t pointCount() const { return x_.size(); }
  std::size_t curveCount() const { return z_.size(); }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& z() const { return z_; }
  bool linearExtrapolation() const { return linear_; }

 private:
  // y = a + b t + c t^2 + d t^3 with t = x - (left end of the piece).
  struct Cubic {
    double a = 0.0, b = 0.0, c = 0.0, d = 0.0;
  };
  // Pieces of curve c are at c * (n - 1) ... c * (n - 1) + n - 2; extrapolation polynomials of
  // curve c are at index c, in t = x - x0 (left) and t = x - x(n-1) (right).
  std::vector<double> x_, z_;
  std::vector<Cubic> akima_, cubic_;
  std::vector<Cubic> left_, right_;
  bool linear_ = false;
};

// The slopes at the knots that the two methods choose, exposed for tests and docs.
// Akima: the weighted average of neighbouring secant slopes, ends extended by two secants
// each (Akima 1970). Cubic: a C2 cubic spline with not-a-knot end conditions.
std::vector<double> akimaSlopes(const std::vector<double>& x, const std::vector<double>& y);
std::vector<double> notAKnotSlopes(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace openmss
