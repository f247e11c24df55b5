#pragma once
// The ADAMS general-purpose functions (STEP, STEP5, HAVSIN, SHF, POLY, CHEBY, FORCOS, FORSIN,
// SWEEP, IMPACT, BISTOP) as defined in docs/expressions.md ("Functions evaluated here"), once for
// every number type of jet.hpp.
//
// Branch points follow ADAMS's inequalities literally: STEP is h0 for x <= x0 and h1 for
// x >= x1; IMPACT is zero for x >= x1; BISTOP is zero for x1 <= x <= x2. The derivative at a
// branch point is the one of the piece that supplies the value there.

#include <numbers>

#include "expr/intrinsics.hpp"
#include "expr/jet.hpp"

namespace openmss::expr::general {

// Cubic step: h0 + (h1 - h0) * s^2 * (3 - 2 s), s = (x - x0) / (x1 - x0). C1 at both ends.
template <typename T>
T step(const T& x, const T& x0, const T& h0, const T& x1, const T& h1) {
  if (valueOf(x) <= valueOf(x0)) return h0;
  if (valueOf(x) >= valueOf(x1)) return h1;
  const T s = (x - x0) / (x1 - x0);
  return h0 + (h1 - h0) * s * s * (3.0 - 2.0 * s);
}

// Quintic step: h0 + (h1 - h0) * s^3 * (10 - 15 s + 6 s^2). C2 at both ends.
template <typename T>
T step5(const T& x, const T& x0, const T& h0, const T& x1, const T& h1) {
  if (valueOf(x) <= valueOf(x0)) return h0;
  if (valueOf(x) >= valueOf(x1)) return h1;
  const T s = (x - x0) / (x1 - x0);
  return h0 + (h1 - h0) * s * s * s * (10.0 + s * (-15.0 + 6.0 * s));
}

// Haversine step: (h1 + h0)/2 + (h1 - h0)/2 * sin(s*pi - pi/2).
template <typename T>
T havsin(const T& x, const T& x0, const T& h0, const T& x1, const T& h1) {
  if (valueOf(x) <= valueOf(x0)) return h0;
  if (valueOf(x) >= valueOf(x1)) return h1;
  const T s = (x - x0) / (x1 - x0);
  const T mean = (h1 + h0) * 0.5;
  const T halfRise = (h1 - h0) * 0.5;
  return mean + halfRise * intrinsic::sin(s * std::numbers::pi - 0.5 * std::numbers::pi);
}

// Simple harmonic function: a * sin(w * (x - x0) - phi) + b.
template <typename T>
T shf(const T& x, const T& x0, const T& a, const T& w, const T& phi, const T& b) {
  return a * intrinsic::sin(w * (x - x0) - phi) + b;
}

// POLY(x, x0, a0, ..., an) = sum a_j (x - x0)^j, evaluated by Horner's rule.
// `args` holds x, x0 and then the coefficients; count >= 3.
template <typename T>
T poly(const T* args, int count) {
  const T u = args[0] - args[1];
  T sum = args[count - 1];
  for (int k = count - 2; k >= 2; --k) sum = sum * u + args[k];
  return sum;
}

// CHEBY(x, x0, a0, ..., an) = sum a_j T_j(x - x0), with the Chebyshev polynomials of the first
// kind T0 = 1, T1 = u, Tj = 2 u T(j-1) - T(j-2).
template <typename T>
T cheby(const T* args, int count) {
  const T u = args[0] - args[1];
  T previous = constant<T>(1.0);  // T0
  T current = u;                  // T1
  T sum = args[2];
  if (count > 3) sum = sum + args[3] * current;
  for (int k = 4; k < count; ++k) {
    const T next = 2.0 * u * current - previous;
    previous = current;
    current = next;
    sum = sum + args[k] * current;
  }
  return sum;
}

// FORCOS(x, x0, w, a0, ..., an) = a0 + sum_{j>=1} a_j cos(j w (x - x0)); FORSIN uses sin.
template <typename T>
T fourierCosine(const T* args, int count) {
  const T phase = args[2] * (args[0] - args[1]);
  T sum = args[3];
  for (int k = 4; k < count; ++k) {
    sum = sum + args[k] * intrinsic::cos(static_cast<double>(k - 3) * phase);
  }
  return sum;
}

template <typename T>
T fourierSine(const T* args, int count) {
  const T phase = args[2] * (args[0] - args[1]);
  T sum = args[3];
  for (int k = 4; k < count; ++k) {
    sum = sum + args[k] * intrinsic::sin(static_cast<double>(k - 3) * phase);
  }
  return sum;
}

// SWEEP(x, a, x0, f0, x1, f1, dx): a linear chirp from f0 to f1 Hz between x0 and x1, with its
// amplitude a faded in by STEP5 over 0..dx. phase(x) is the cycle count, continuous at x0, x1.
template <typename T>
T sweep(const T& x, const T& a, const T& x0, const T& f0, const T& x1, const T& f1, const T& dx) {
  T cycles;
  if (valueOf(x) <= valueOf(x0)) {
    cycles = f0 * x;
  } else if (valueOf(x) < valueOf(x1)) {
    const T u = x - x0;
    cycles = f0 * u + (f1 - f0) / (2.0 * (x1 - x0)) * u * u + f0 * x0;
  } else {
    cycles = f1 * x - (f1 - f0) * 0.5 * (x1 + x0);
  }
  const T zero = constant<T>(0.0);
  const T ramp = step5(x, zero, zero, dx, constant<T>(1.0));
  return ramp * a * intrinsic::sin(2.0 * std::numbers::pi * cycles);
}

// IMPACT(x, xdot, x1, k, e, cmax, d): one-sided contact force, active for x < x1.
// max(0, k (x1 - x)^e - STEP(x, x1 - d, cmax, x1, 0) * xdot).
template <typename T>
T impact(const T& x, const T& xdot, const T& x1, const T& k, const T& e, const T& cmax,
         const T& d) {
  const T zero = constant<T>(0.0);
  if (valueOf(x) >= valueOf(x1)) return zero;
  const T damping = step(x, x1 - d, cmax, x1, zero);
  const T force = k * intrinsic::power(x1 - x, e) - damping * xdot;
  return valueOf(force) > 0.0 ? force : zero;
}

// BISTOP(x, xdot, x1, x2, k, e, cmax, d): a gap with stops at x1 (pushes up) and x2 (pushes
// down); free between them.
template <typename T>
T bistop(const T& x, const T& xdot, const T& x1, const T& x2, const T& k, const T& e, const T& cmax,
         const T& d) {
  const T zero = constant<T>(0.0);
  if (valueOf(x) < valueOf(x1)) {
    const T damping = step(x, x1 - d, cmax, x1, zero);
    const T force = k * intrinsic::power(x1 - x, e) - damping * xdot;
    return valueOf(force) > 0.0 ? force : zero;
  }
  if (valueOf(x) > valueOf(x2)) {
    const T damping = step(x, x2, zero, x2 + d, cmax);
    const T force = -k * intrinsic::power(x - x2, e) - damping * xdot;
    return valueOf(force) < 0.0 ? force : zero;
  }
  return zero;
}

}  // namespace openmss::expr::general
