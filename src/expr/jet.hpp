#pragma once
// Number types that carry derivatives through the built-in functions.
//
// Every built-in function is written once as a template over its number type and instantiated
// for three types:
//  * double  - plain values (the integrator's inner loop);
//  * Jet1    - value and one directional first derivative; the reverse-mode evaluator uses it
//              to obtain a function's exact partial with respect to one argument;
//  * Jet2    - value, first and second derivative along one parameter (TIME for MOTION).
// Only the value takes part in comparisons, so a branch (STEP, IF, MAX, ...) is chosen by the
// value and the derivatives are those of the selected piece.

#include <cmath>

namespace openmss::expr {

struct Jet1 {
  double v;  // value
  double d;  // derivative along the seeded direction
};

// Members are left without initializers on purpose: evaluation work arrays of Jet2 are declared
// uninitialized on the stack, and every slot is written before it is read.
struct Jet2 {
  double v;   // value
  double d1;  // first derivative
  double d2;  // second derivative
};

inline double valueOf(double x) { return x; }
inline double valueOf(const Jet1& x) { return x.v; }
inline double valueOf(const Jet2& x) { return x.v; }

// A number of type T that is a constant (all derivatives zero).
template <typename T>
T constant(double x);
template <>
inline double constant<double>(double x) {
  return x;
}
template <>
inline Jet1 constant<Jet1>(double x) {
  return {x, 0.0};
}
template <>
inline Jet2 constant<Jet2>(double x) {
  return {x, 0.0, 0.0};
}

inline bool hasDerivative(double) { return false; }
inline bool hasDerivative(const Jet1& x) { return x.d != 0.0; }
inline bool hasDerivative(const Jet2& x) { return x.d1 != 0.0 || x.d2 != 0.0; }

// Chain rule for g(u). g is the value at u; firstDerivative() and secondDerivative() give g'
// and g'' there and are only called when the number type needs them, so plain doubles pay for
// the value alone.
template <typename F1, typename F2>
double chain(double, double g, F1&&, F2&&) {
  return g;
}
template <typename F1, typename F2>
Jet1 chain(const Jet1& u, double g, F1&& firstDerivative, F2&&) {
  return {g, firstDerivative() * u.d};
}
template <typename F1, typename F2>
Jet2 chain(const Jet2& u, double g, F1&& firstDerivative, F2&& secondDerivative) {
  const double g1 = firstDerivative();
  return {g, g1 * u.d1, secondDerivative() * u.d1 * u.d1 + g1 * u.d2};
}

// Chain rule for g(a, b) given its value, gradient and Hessian at the values of a and b.
struct BinaryPartials {
  double g, ga, gb, gaa, gab, gbb;
};
inline double chain2(double, double, const BinaryPartials& p) { return p.g; }
inline Jet1 chain2(const Jet1& a, const Jet1& b, const BinaryPartials& p) {
  return {p.g, p.ga * a.d + p.gb * b.d};
}
inline Jet2 chain2(const Jet2& a, const Jet2& b, const BinaryPartials& p) {
  return {p.g, p.ga * a.d1 + p.gb * b.d1,
          p.ga * a.d2 + p.gb * b.d2 + p.gaa * a.d1 * a.d1 + 2.0 * p.gab * a.d1 * b.d1 +
              p.gbb * b.d1 * b.d1};
}

// --- Arithmetic -------------------------------------------------------------------------------

inline Jet1 operator-(const Jet1& a) { return {-a.v, -a.d}; }
inline Jet1 operator+(const Jet1& a, const Jet1& b) { return {a.v + b.v, a.d + b.d}; }
inline Jet1 operator-(const Jet1& a, const Jet1& b) { return {a.v - b.v, a.d - b.d}; }
inline Jet1 operator*(const Jet1& a, const Jet1& b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
inline Jet1 operator/(const Jet1& a, const Jet1& b) {
  const double q = a.v / b.v;
  return {q, (a.d - q * b.d) / b.v};
}
inline Jet1 operator+(const Jet1& a, double b) { return {a.v + b, a.d}; }
inline Jet1 operator+(double a, const Jet1& b) { return {a + b.v, b.d}; }
inline Jet1 operator-(const Jet1& a, double b) { return {a.v - b, a.d}; }
inline Jet1 operator-(double a, const Jet1& b) { return {a - b.v, -b.d}; }
inline Jet1 operator*(const Jet1& a, double b) { return {a.v * b, a.d * b}; }
inline Jet1 operator*(double a, const Jet1& b) { return {a * b.v, a * b.d}; }
inline Jet1 operator/(const Jet1& a, double b) { return {a.v / b, a.d / b}; }
inline Jet1 operator/(double a, const Jet1& b) { return constant<Jet1>(a) / b; }

inline Jet2 operator-(const Jet2& a) { return {-a.v, -a.d1, -a.d2}; }
inline Jet2 operator+(const Jet2& a, const Jet2& b) {
  return {a.v + b.v, a.d1 + b.d1, a.d2 + b.d2};
}
inline Jet2 operator-(const Jet2& a, const Jet2& b) {
  return {a.v - b.v, a.d1 - b.d1, a.d2 - b.d2};
}
inline Jet2 operator*(const Jet2& a, const Jet2& b) {
  return {a.v * b.v, a.d1 * b.v + a.v * b.d1, a.d2 * b.v + 2.0 * a.d1 * b.d1 + a.v * b.d2};
}
// q = a / b, so a = q b and a'' = q'' b + 2 q' b' + q b''.
inline Jet2 operator/(const Jet2& a, const Jet2& b) {
  const double q = a.v / b.v;
  const double q1 = (a.d1 - q * b.d1) / b.v;
  const double q2 = (a.d2 - 2.0 * q1 * b.d1 - q * b.d2) / b.v;
  return {q, q1, q2};
}
inline Jet2 operator+(const Jet2& a, double b) { return {a.v + b, a.d1, a.d2}; }
inline Jet2 operator+(double a, const Jet2& b) { return {a + b.v, b.d1, b.d2}; }
inline Jet2 operator-(const Jet2& a, double b) { return {a.v - b, a.d1, a.d2}; }
inline Jet2 operator-(double a, const Jet2& b) { return {a - b.v, -b.d1, -b.d2}; }
inline Jet2 operator*(const Jet2& a, double b) { return {a.v * b, a.d1 * b, a.d2 * b}; }
inline Jet2 operator*(double a, const Jet2& b) { return {a * b.v, a * b.d1, a * b.d2}; }
inline Jet2 operator/(const Jet2& a, double b) { return {a.v / b, a.d1 / b, a.d2 / b}; }
inline Jet2 operator/(double a, const Jet2& b) { return constant<Jet2>(a) / b; }

}  // namespace openmss::expr
