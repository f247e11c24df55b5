#pragma once
// CURVE/id, MATRIX=id: a B-spline space curve evaluated by the CURVE(alpha, iord, comp, id)
// function (docs/theory.md, "Interpolation of SPLINE and CURVE data").
//
// ADAMS's CURVE statement fixes the parameter range (-1..1), the order (ORDER, default 4), that the
// matrix rows are control points or (CURVE_POINTS) points on the curve, and that a CLOSED curve is
// continuous in its first and second derivatives across the closure. What it leaves open is
// fixed here and documented: uniform knots, and for CURVE_POINTS uniform parameter values with
// knots at averages of them (de Boor), so a cubic in alpha sampled at uniform alpha is
// reproduced exactly.
//
// In common for the same reason as Spline; immutable after construction; evaluation allocates
// nothing (orders up to kMaxOrder).

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace openmss {

// A curve given by code instead of points: CURVE/id, FUNCTION=USER(...) (CURSUB,
// src/user/curve_routine.cpp). Same contract as BSplineCurve::derivatives.
class CurveEvaluator {
 public:
  virtual ~CurveEvaluator() = default;
  virtual void derivatives(double alpha, int comp, double out[5]) const = 0;
};

class BSplineCurve {
 public:
  static constexpr int kMaxOrder = 8;
  static constexpr int kDerivatives = 5;  // value and four derivatives (iord 2 plus a time jet)

  // points: the MATRIX rows (x, y, z). Returns an empty string when the input defines a curve,
  // otherwise what is wrong (for a diagnostic).
  static std::string check(const std::vector<std::array<double, 3>>& points, int order,
                           bool closed);

  // Precondition: check(...) returned "".
  BSplineCurve(const std::vector<std::array<double, 3>>& points, int order, bool closed,
               bool throughPoints);
  // A user curve (CURSUB) over [minPar, maxPar]: derivatives() asks `user`.
  BSplineCurve(std::shared_ptr<const CurveEvaluator> user, double minPar, double maxPar,
               bool closed)
      : minPar_(minPar), maxPar_(maxPar), closed_(closed), user_(std::move(user)) {}

  // d^k C / d alpha^k (k = 0..4) of component comp (0, 1, 2 = x, y, z) at alpha. A closed curve
  // repeats with period 2; an open one continues its end polynomial pieces outside [-1, 1].
  void derivatives(double alpha, int comp, double out[kDerivatives]) const;

  int order() const { return order_; }
  bool closed() const { return closed_; }
  // The parameter's range: -1..1, or a user curve's MINPAR..MAXPAR.
  double minParameter() const { return minPar_; }
  double maxParameter() const { return maxPar_; }

 private:
  // One B-spline: knots, control points (x, y, z), degree.
  struct Piecewise {
    std::vector<double> knots;
    std::vector<std::array<double, 3>> points;
    int degree = 0;
  };
  static double deBoor(const Piecewise& s, double u, int comp);

  std::array<Piecewise, kDerivatives> hodographs_;  // the curve and its derivative curves in u
  double uMin_ = 0.0, uMax_ = 1.0;
  double minPar_ = -1.0, maxPar_ = 1.0;
  int order_ = 4;
  bool closed_ = false;
  std::shared_ptr<const CurveEvaluator> user_;
};

}  // namespace openmss
