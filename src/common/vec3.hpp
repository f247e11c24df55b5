#pragma once
// Small 3-vectors, 3x3 matrices and quaternions templated on the scalar so that the same code
// runs on double and on Dual<> (see dual.hpp).

#include <Eigen/Dense>

#include "common/dual.hpp"

namespace openmss {

template <class T>
struct V3 {
  T x{}, y{}, z{};
  V3() = default;
  V3(T a, T b, T c) : x(a), y(b), z(c) {}
  template <class U>
  static V3 from(const V3<U>& o) { return {T(o.x), T(o.y), T(o.z)}; }
  static V3 from(const Eigen::Vector3d& o) { return {T(o.x()), T(o.y()), T(o.z())}; }
  T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend V3 operator-(const V3& a) { return {-a.x, -a.y, -a.z}; }
  friend V3 operator*(const T& s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend V3 operator*(const V3& a, const T& s) { return {s * a.x, s * a.y, s * a.z}; }
  V3& operator+=(const V3& b) { x += b.x; y += b.y; z += b.z; return *this; }
  V3& operator-=(const V3& b) { x -= b.x; y -= b.y; z -= b.z; return *this; }
};

template <class T>
T dot(const V3<T>& a, const V3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T norm(const V3<T>& a) { return sqrtOf(dot(a, a)); }

inline Eigen::Vector3d toEigen(const V3<double>& a) { return {a.x, a.y, a.z}; }

// 3x3 matrix stored by columns: c[k] is column k.
template <class T>
struct M3 {
  V3<T> c[3];
  V3<T> operator*(const V3<T>& v) const { return c[0] * v.x + c[1] * v.y + c[2] * v.z; }
  // this^T * v
  V3<T> tmul(const V3<T>& v) const { return {dot(c[0], v), dot(c[1], v), dot(c[2], v)}; }
  M3 operator*(const M3& o) const { return {{(*this) * o.c[0], (*this) * o.c[1], (*this) * o.c[2]}}; }
  M3 transpose() const {
    M3 t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) t.c[j][i] = c[i][j];
    return t;
  }
  T at(int row, int col) const { return c[col][row]; }
  template <class U>
  static M3 from(const M3<U>& o) { return {{V3<T>::from(o.c[0]), V3<T>::from(o.c[1]), V3<T>::from(o.c[2])}}; }
  static M3 from(const Eigen::Matrix3d& m) {
    M3 r;
    for (int j = 0; j < 3; ++j) r.c[j] = V3<T>(T(m(0, j)), T(m(1, j)), T(m(2, j)));
    return r;
  }
};

inline Eigen::Matrix3d toEigen(const M3<double>& m) {
  Eigen::Matrix3d r;
  for (int j = 0; j < 3; ++j) r.col(j) = toEigen(m.c[j]);
  return r;
}

// Euler parameters (unit quaternion) e = (e0, e1, e2, e3), e0 the scalar part.
template <class T>
struct Quat {
  T e0{}, e1{}, e2{}, e3{};
};

// Rotation matrix of a quaternion, quadratic form (exact rotation when |e| = 1; the model keeps
// |e| = 1 as an equation of the DAE).
template <class T>
M3<T> rotationOf(const Quat<T>& q) {
  const T& a = q.e0; const T& b = q.e1; const T& c = q.e2; const T& d = q.e3;
  M3<T> m;
  m.c[0] = {a * a + b * b - c * c - d * d, 2.0 * (b * c + a * d), 2.0 * (b * d - a * c)};
  m.c[1] = {2.0 * (b * c - a * d), a * a - b * b + c * c - d * d, 2.0 * (c * d + a * b)};
  m.c[2] = {2.0 * (b * d + a * c), 2.0 * (c * d - a * b), a * a - b * b - c * c + d * d};
  return m;
}

}  // namespace openmss
