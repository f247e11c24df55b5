#pragma once
// Forward-mode AD along N directions at once (the element-local Newton matrix,
// local_newton_matrix.hpp): one evaluation of an equation yields its derivatives with respect
// to all the positions it reads, the value being computed once instead of N times.

#include <cmath>

#include "common/vec3.hpp"

namespace openmss::mechanics {

template <int N>
struct DualVec {
  double v = 0.0;
  double d[N] = {};
  DualVec() = default;
  DualVec(double value) : v(value) {}  // NOLINT: constants mix freely with duals
  friend DualVec operator+(const DualVec& a, const DualVec& b) {
    DualVec r(a.v + b.v);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] + b.d[k];
    return r;
  }
  friend DualVec operator-(const DualVec& a, const DualVec& b) {
    DualVec r(a.v - b.v);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] - b.d[k];
    return r;
  }
  friend DualVec operator-(const DualVec& a) {
    DualVec r(-a.v);
    for (int k = 0; k < N; ++k) r.d[k] = -a.d[k];
    return r;
  }
  friend DualVec operator*(const DualVec& a, const DualVec& b) {
    DualVec r(a.v * b.v);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
    return r;
  }
  friend DualVec operator*(double a, const DualVec& b) {
    DualVec r(a * b.v);
    for (int k = 0; k < N; ++k) r.d[k] = a * b.d[k];
    return r;
  }
  friend DualVec operator*(const DualVec& b, double a) { return a * b; }
  // Division as Dual's (common/dual.hpp), operation for operation, so that each direction
  // carries the same bits as a Dual<double> seeded along it.
  friend DualVec operator/(const DualVec& a, const DualVec& b) {
    const double inv = 1.0 / b.v;
    DualVec r(a.v * inv);
    for (int k = 0; k < N; ++k) r.d[k] = (a.d[k] - a.v * inv * b.d[k]) * inv;
    return r;
  }
  friend DualVec operator/(const DualVec& a, double b) {
    DualVec r(a.v / b);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] / b;
    return r;
  }
  // The functions the force elements' laws use (ForceElements::stateLocalLoads), as Dual's;
  // hidden friends (found by argument-dependent lookup only), so that they do not hide the
  // double versions from the rest of the namespace.
  friend double valueOf(const DualVec& x) { return x.v; }
  friend DualVec sqrtOf(const DualVec& a) {
    const double s = std::sqrt(a.v);
    DualVec r(s);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] / (2.0 * s);
    return r;
  }
  friend DualVec atan2Of(const DualVec& y, const DualVec& x) {
    const double r2 = x.v * x.v + y.v * y.v;
    DualVec r(std::atan2(y.v, x.v));
    for (int k = 0; k < N; ++k) r.d[k] = (x.v * y.d[k] - y.v * x.d[k]) / r2;
    return r;
  }
};

// dot and cross of multi-direction vectors in one pass over the directions, without the
// temporaries of the generic V3 versions (common/vec3.hpp), which the compiler left as calls
// returning through memory. Found by argument-dependent lookup, more specialised than the
// generic templates; the operations and their order are those of the generic ones, so the
// numbers are the same bits (docs/performance.md, "The element-local Newton matrix, cheaper").
template <int N>
DualVec<N> dot(const V3<DualVec<N>>& a, const V3<DualVec<N>>& b) {
  DualVec<N> r(a.x.v * b.x.v + a.y.v * b.y.v + a.z.v * b.z.v);
  for (int k = 0; k < N; ++k)
    r.d[k] = (a.x.d[k] * b.x.v + a.x.v * b.x.d[k]) + (a.y.d[k] * b.y.v + a.y.v * b.y.d[k]) +
             (a.z.d[k] * b.z.v + a.z.v * b.z.d[k]);
  return r;
}

// a * b - c * d, as the generic DualVec operators compute it.
template <int N>
DualVec<N> productDifference(const DualVec<N>& a, const DualVec<N>& b, const DualVec<N>& c,
                             const DualVec<N>& d) {
  DualVec<N> r(a.v * b.v - c.v * d.v);
  for (int k = 0; k < N; ++k)
    r.d[k] = (a.d[k] * b.v + a.v * b.d[k]) - (c.d[k] * d.v + c.v * d.d[k]);
  return r;
}

template <int N>
V3<DualVec<N>> cross(const V3<DualVec<N>>& a, const V3<DualVec<N>>& b) {
  return {productDifference(a.y, b.z, a.z, b.y), productDifference(a.z, b.x, a.x, b.z),
          productDifference(a.x, b.y, a.y, b.x)};
}

}  // namespace openmss::mechanics
