#pragma once
// Forward-mode automatic differentiation with one derivative direction. Nesting
// Dual<Dual<double>> gives exact second directional derivatives. The mechanics writes each
// equation once, templated on the scalar, and gets exact Jacobians by evaluating it on duals:
// no finite differences and no hand-derived second derivatives to keep in step.

#include <cmath>

namespace openmss {

template <class T>
struct Dual {
  T v{};  // value
  T d{};  // derivative along the seeded direction

  Dual() = default;
  Dual(double value) : v(value), d(0.0) {}  // NOLINT: constants mix freely with duals
  Dual(T value, T derivative) : v(value), d(derivative) {}

  Dual& operator+=(const Dual& o) { v += o.v; d += o.d; return *this; }
  Dual& operator-=(const Dual& o) { v -= o.v; d -= o.d; return *this; }
  Dual& operator*=(const Dual& o) { d = d * o.v + v * o.d; v *= o.v; return *this; }
  Dual& operator/=(const Dual& o) { *this = *this / o; return *this; }
  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator*(Dual a, const Dual& b) { return a *= b; }
  friend Dual operator/(const Dual& a, const Dual& b) {
    T inv = T(1.0) / b.v;
    return {a.v * inv, (a.d - a.v * inv * b.d) * inv};
  }
  friend Dual operator-(const Dual& a) { return {-a.v, -a.d}; }
  friend Dual operator+(const Dual& a) { return a; }
  friend Dual operator+(double a, const Dual& b) { return Dual(a) + b; }
  friend Dual operator-(double a, const Dual& b) { return Dual(a) - b; }
  friend Dual operator*(double a, const Dual& b) { return {a * b.v, a * b.d}; }
  friend Dual operator*(const Dual& b, double a) { return {a * b.v, a * b.d}; }
  friend Dual operator/(const Dual& a, double b) { return {a.v / b, a.d / b}; }
  friend Dual operator/(double a, const Dual& b) { return Dual(a) / b; }
  friend Dual operator+(const Dual& b, double a) { return Dual(a) + b; }
  friend Dual operator-(const Dual& b, double a) { return b - Dual(a); }
};

// Value of a possibly nested dual.
inline double valueOf(double x) { return x; }
template <class T>
double valueOf(const Dual<T>& x) { return valueOf(x.v); }

inline double sqrtOf(double x) { return std::sqrt(x); }
inline double sinOf(double x) { return std::sin(x); }
inline double cosOf(double x) { return std::cos(x); }
inline double atan2Of(double y, double x) { return std::atan2(y, x); }
inline double acosOf(double x) { return std::acos(x); }

template <class T>
Dual<T> sqrtOf(const Dual<T>& a) {
  T s = sqrtOf(a.v);
  return {s, a.d / (2.0 * s)};
}
template <class T>
Dual<T> sinOf(const Dual<T>& a) { return {sinOf(a.v), cosOf(a.v) * a.d}; }
template <class T>
Dual<T> cosOf(const Dual<T>& a) { return {cosOf(a.v), -sinOf(a.v) * a.d}; }
template <class T>
Dual<T> atan2Of(const Dual<T>& y, const Dual<T>& x) {
  T r2 = x.v * x.v + y.v * y.v;
  return {atan2Of(y.v, x.v), (x.v * y.d - y.v * x.d) / r2};
}
template <class T>
Dual<T> acosOf(const Dual<T>& a) {
  return {acosOf(a.v), -a.d / sqrtOf(1.0 - a.v * a.v)};
}

}  // namespace openmss
