#pragma once
// The FORTRAN-77 intrinsics of ADAMS expressions and the `**` operator, written once for every
// number type of jet.hpp (double, Jet1, Jet2) so that values, first partials and time jets all
// come from the same definition.
//
// Where a function has a kink or a jump, the derivative is the one of the piece that the value
// selects (e.g. d|x|/dx = +1 at x = 0, because ABS(0) is computed by the x >= 0 piece).

#include <cmath>
#include <numbers>
#include <type_traits>

#include "expr/jet.hpp"

namespace openmss::expr::intrinsic {

template <typename T>
T abs(const T& u) {
  return valueOf(u) >= 0.0 ? u : -u;
}

template <typename T>
T sqrt(const T& u) {
  const double x = valueOf(u);
  const double s = std::sqrt(x);
  return chain(
      u, s, [&] { return 0.5 / s; }, [&] { return -0.25 / (s * x); });
}

template <typename T>
T exp(const T& u) {
  const double e = std::exp(valueOf(u));
  return chain(
      u, e, [&] { return e; }, [&] { return e; });
}

template <typename T>
T log(const T& u) {
  const double x = valueOf(u);
  return chain(
      u, std::log(x), [&] { return 1.0 / x; }, [&] { return -1.0 / (x * x); });
}

template <typename T>
T log10(const T& u) {
  const double x = valueOf(u);
  constexpr double kScale = 1.0 / std::numbers::ln10;
  return chain(
      u, std::log10(x), [&] { return kScale / x; }, [&] { return -kScale / (x * x); });
}

template <typename T>
T sin(const T& u) {
  const double x = valueOf(u);
  const double s = std::sin(x);
  return chain(
      u, s, [&] { return std::cos(x); }, [&] { return -s; });
}

template <typename T>
T cos(const T& u) {
  const double x = valueOf(u);
  const double c = std::cos(x);
  return chain(
      u, c, [&] { return -std::sin(x); }, [&] { return -c; });
}

template <typename T>
T tan(const T& u) {
  const double t = std::tan(valueOf(u));
  return chain(
      u, t, [&] { return 1.0 + t * t; }, [&] { return 2.0 * t * (1.0 + t * t); });
}

template <typename T>
T asin(const T& u) {
  const double x = valueOf(u);
  return chain(
      u, std::asin(x), [&] { return 1.0 / std::sqrt(1.0 - x * x); },
      [&] { return x / ((1.0 - x * x) * std::sqrt(1.0 - x * x)); });
}

template <typename T>
T acos(const T& u) {
  const double x = valueOf(u);
  return chain(
      u, std::acos(x), [&] { return -1.0 / std::sqrt(1.0 - x * x); },
      [&] { return -x / ((1.0 - x * x) * std::sqrt(1.0 - x * x)); });
}

template <typename T>
T atan(const T& u) {
  const double x = valueOf(u);
  return chain(
      u, std::atan(x), [&] { return 1.0 / (1.0 + x * x); },
      [&] { return -2.0 * x / ((1.0 + x * x) * (1.0 + x * x)); });
}

template <typename T>
T sinh(const T& u) {
  const double x = valueOf(u);
  const double s = std::sinh(x);
  return chain(
      u, s, [&] { return std::cosh(x); }, [&] { return s; });
}

template <typename T>
T cosh(const T& u) {
  const double x = valueOf(u);
  const double c = std::cosh(x);
  return chain(
      u, c, [&] { return std::sinh(x); }, [&] { return c; });
}

template <typename T>
T tanh(const T& u) {
  const double t = std::tanh(valueOf(u));
  return chain(
      u, t, [&] { return 1.0 - t * t; }, [&] { return -2.0 * t * (1.0 - t * t); });
}

// ATAN2(y, x): the angle of the point (x, y), in (-pi, pi].
template <typename T>
T atan2(const T& y, const T& x) {
  const double yv = valueOf(y);
  const double xv = valueOf(x);
  if constexpr (std::is_same_v<T, double>) {
    return std::atan2(yv, xv);
  } else {
    const double r2 = xv * xv + yv * yv;
    const double r4 = r2 * r2;
    BinaryPartials p{};
    p.g = std::atan2(yv, xv);
    p.ga = xv / r2;
    p.gb = -yv / r2;
    p.gaa = -2.0 * xv * yv / r4;
    p.gab = (yv * yv - xv * xv) / r4;
    p.gbb = 2.0 * xv * yv / r4;
    return chain2(y, x, p);
  }
}

// a ** b. With a constant exponent the logarithm of the base is never formed, so negative
// bases with whole exponents (x**2 at x < 0) have finite derivatives; b = 0 and b = 1 give
// exact zeros instead of 0 * inf at a = 0.
template <typename T>
T power(const T& a, const T& b) {
  const double x = valueOf(a);
  const double n = valueOf(b);
  const double value = std::pow(x, n);
  if constexpr (std::is_same_v<T, double>) {
    return value;
  } else {
    // n x^(n-1) = n x^n / x saves a second pow away from x = 0.
    const auto first = [&] {
      if (n == 0.0) return 0.0;
      return x != 0.0 ? n * value / x : n * std::pow(x, n - 1.0);
    };
    const auto second = [&] {
      return (n == 0.0 || n == 1.0) ? 0.0 : n * (n - 1.0) * std::pow(x, n - 2.0);
    };
    if (!hasDerivative(b)) return chain(a, value, first, second);
    const double lnx = std::log(x);
    BinaryPartials p{};
    p.g = value;
    p.ga = first();
    p.gb = value * lnx;
    p.gaa = second();
    p.gab = std::pow(x, n - 1.0) * (1.0 + n * lnx);
    p.gbb = value * lnx * lnx;
    return chain2(a, b, p);
  }
}

// MAX and MIN take two or more arguments (FORTRAN); the first extreme one wins a tie.
template <typename T>
T maximum(const T* args, int count) {
  int best = 0;
  for (int k = 1; k < count; ++k) {
    if (valueOf(args[k]) > valueOf(args[best])) best = k;
  }
  return args[best];
}

template <typename T>
T minimum(const T* args, int count) {
  int best = 0;
  for (int k = 1; k < count; ++k) {
    if (valueOf(args[k]) < valueOf(args[best])) best = k;
  }
  return args[best];
}

// AINT: truncation toward zero. Piecewise constant, so every derivative is zero.
template <typename T>
T aint(const T& a) {
  return constant<T>(std::trunc(valueOf(a)));
}

// ANINT: nearest whole number, halves away from zero (std::round has exactly that rule).
template <typename T>
T anint(const T& a) {
  return constant<T>(std::round(valueOf(a)));
}

// MOD(a, b) = a - AINT(a / b) * b: the remainder carries the sign of a.
template <typename T>
T mod(const T& a, const T& b) {
  return a - constant<T>(std::trunc(valueOf(a) / valueOf(b))) * b;
}

// SIGN(a, b) = |a| when b >= 0, -|a| when b < 0.
template <typename T>
T sign(const T& a, const T& b) {
  const T magnitude = abs(a);
  return valueOf(b) >= 0.0 ? magnitude : -magnitude;
}

// DIM(a, b) = a - b when a > b, else 0 (the positive difference).
template <typename T>
T dim(const T& a, const T& b) {
  return valueOf(a) > valueOf(b) ? a - b : constant<T>(0.0);
}

}  // namespace openmss::expr::intrinsic
