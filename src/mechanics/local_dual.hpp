#pragma once
// Forward-mode AD along N directions at once (the element-local Newton matrix,
// local_newton_matrix.hpp): one evaluation of an equation yields its derivatives with respect
// to all the positions it reads, the value being computed once instead of N times.

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
};

}  // namespace openmss::mechanics
