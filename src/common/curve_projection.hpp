#pragma once
// The projection of a point on a CURVE, for PTCV, the point-to-curve constraint (docs/theory.md
// §5d): marker I's origin stays on a CURVE fixed in the RM marker's frame. The curve parameter is
// not an unknown of the DAE: at any configuration it is the parameter alpha* of the curve point
// nearest to I,
//     g(alpha) = (c(alpha) - q) . c'(alpha) = 0,   q = A_RM^T (p_I - o_RM)  (RM coordinates),
// and the constraint is the two components of q - c(alpha*) normal to the tangent:
//     e_k = (q - c(alpha*)) . n_k,  n_1 = unit(h x t),  n_2 = t x n_1,  t = unit(c'(alpha*)),
// h a fixed axis of RM (the one least aligned with the curve's tangents, chosen per PTCV).
// On the curve q = c(alpha*), so the equations' gradient is the two normals: exactly the two
// degrees of freedom ADAMS's PTCV removes, and the reaction has no tangential component.
//
// Derivatives: alpha* is found in double (a coarse search over the curve, then Newton on g);
// on a dual scalar, Newton steps taken from alpha* in the dual arithmetic give its exact
// derivatives by the implicit function theorem (each step doubles the order of exactness:
// one step for first derivatives, two for second), so every Jacobian, constraint rate and
// acceleration term the mechanics takes by forward-mode AD is exact.

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "common/bspline_curve.hpp"
#include "common/dual.hpp"
#include "common/vec3.hpp"

namespace openmss {

// f(x) on any dual depth from f and its derivatives at valueOf(x): d[k] = d^k f / dx^k,
// d[0..n) available (higher ones read as 0: exact for a B-spline of degree < n).
inline double composeScalar(const double* d, int n, double /*x*/) { return n > 0 ? d[0] : 0.0; }
template <class T>
Dual<T> composeScalar(const double* d, int n, const Dual<T>& x) {
  if (n <= 0) return Dual<T>(T(0.0), T(0.0));
  return Dual<T>(composeScalar(d, n, x.v), composeScalar(d + 1, n - 1, x.v) * x.d);
}

// d^k c / dalpha^k (RM coordinates) at alpha, k = 0, 1, 2, on any scalar.
template <class S>
V3<S> curveDerivative(const BSplineCurve& curve, const S& alpha, int k) {
  V3<S> out;
  for (int comp = 0; comp < 3; ++comp) {
    double d[BSplineCurve::kDerivatives];
    curve.derivatives(valueOf(alpha), comp, d);
    out[comp] = composeScalar(d + k, BSplineCurve::kDerivatives - k, alpha);
  }
  return out;
}

// Newton on g from a warm start (the parameter of the last accepted state): accepted when it
// converges within 12 steps of at most one sample interval each, at a minimum (g' > 0), no
// farther than 4 sample intervals from the start; otherwise false (the caller searches the
// whole curve). The result depends only on the start, so runs stay bit-identical.
inline bool localCurveParameter(const BSplineCurve& curve, const V3<double>& q, int samples,
                                double start, double& out) {
  const double step = (curve.maxParameter() - curve.minParameter()) / samples;
  double a = start;
  bool closing = false;  // the step before was already small: this one polishes
  for (int it = 0; it < 12; ++it) {
    const V3<double> c = curveDerivative(curve, a, 0), c1 = curveDerivative(curve, a, 1),
                     c2 = curveDerivative(curve, a, 2);
    const double g = dot(c - q, c1), dg = dot(c1, c1) + dot(c - q, c2);
    if (!(dg > 0.0)) return false;
    const double da = std::max(-step, std::min(step, -g / dg));
    a += da;
    if (std::abs(a - start) > 4.0 * step) return false;
    if (closing) {
      out = a;
      return true;
    }
    closing = std::abs(da) < 1e-9 * (1.0 + std::abs(a));
  }
  return false;
}

// The parameter of the curve point nearest to q (RM coordinates), double: from the warm start
// when given (finite) and the local Newton accepts it, otherwise the best of a coarse sampling
// of [-1, 1] refined by Newton on g. Deterministic: the samples and iteration count are fixed.
// A closed curve is periodic in alpha; an open one is extended past its ends by its end pieces
// (BSplineCurve), so alpha may leave [-1, 1] when the point runs off an end (the run stops at
// the next accepted state, ExpressionRunState::curveRunOff).
inline double nearestCurveParameter(const BSplineCurve& curve, const V3<double>& q, int samples,
                                    const double* warm = nullptr) {
  if (warm && std::isfinite(*warm)) {
    double a = 0.0;
    if (localCurveParameter(curve, q, samples, *warm, a)) return a;
  }
  auto point = [&](double a) { return curveDerivative(curve, a, 0); };
  // Samples over the parameter range (-1..1, or a user curve's MINPAR..MAXPAR).
  const double a0 = curve.minParameter(), span = curve.maxParameter() - a0;
  double best = a0, bestDistance = INFINITY;
  for (int s = 0; s <= samples; ++s) {
    const double a = a0 + span * s / samples;
    const V3<double> d = point(a) - q;
    const double distance = dot(d, d);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = a;
    }
  }
  const double step = span / samples;
  double a = best;
  for (int it = 0; it < 50; ++it) {
    const V3<double> c = point(a), c1 = curveDerivative(curve, a, 1),
                     c2 = curveDerivative(curve, a, 2);
    const double g = dot(c - q, c1), dg = dot(c1, c1) + dot(c - q, c2);
    if (!(dg > 0.0)) break;  // not a minimum's neighbourhood: keep the sample
    double da = -g / dg;
    // Stay within a sample interval of the coarse minimum (no jump to another branch).
    da = std::max(-step, std::min(step, da));
    a += da;
    if (std::abs(da) < 1e-15 * (1.0 + std::abs(a))) break;
  }
  return a;
}

// The two equations e_0, e_1 of a PTCV for I's origin q in RM coordinates (any scalar).
template <class S>
std::array<S, 2> pointCurveResiduals(const BSplineCurve& curve, int helperAxis, int samples,
                                     const V3<S>& q, const double* warm = nullptr) {
  const V3<double> q0(valueOf(q[0]), valueOf(q[1]), valueOf(q[2]));
  S alpha(nearestCurveParameter(curve, q0, samples, warm));
  if constexpr (!std::is_same_v<S, double>) {
    for (int step = 0; step < 2; ++step) {  // exact first and second derivatives of alpha*
      const V3<S> c = curveDerivative(curve, alpha, 0), c1 = curveDerivative(curve, alpha, 1),
                  c2 = curveDerivative(curve, alpha, 2);
      const S g = dot(c - q, c1), dg = dot(c1, c1) + dot(c - q, c2);
      alpha = alpha - g / dg;
    }
  }
  const V3<S> c = curveDerivative(curve, alpha, 0);
  const V3<S> c1 = curveDerivative(curve, alpha, 1);
  const V3<S> t = c1 * (S(1.0) / norm(c1));
  V3<S> h(S(0.0), S(0.0), S(0.0));
  h[helperAxis] = S(1.0);
  V3<S> n1 = cross(h, t);
  n1 = n1 * (S(1.0) / norm(n1));
  const V3<S> n2 = cross(t, n1);
  const V3<S> d = q - c;
  return {dot(d, n1), dot(d, n2)};
}

}  // namespace openmss
