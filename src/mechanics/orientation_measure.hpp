#pragma once
// ORIENT(code, component, i, j) on any scalar (double or nested Dual<>), so that force and
// VARIABLE functions reading it get exact partial derivatives. The formulas are those of
// common/rotation.cpp (quaternionFromMatrix, bodyFixedAngles), which the double-only outputs
// use; the branch choices (largest pivot of the quaternion extraction, gimbal-lock fallback)
// are made on values, so the derivative is that of the branch taken.

#include <cmath>

#include "common/dual.hpp"
#include "common/rotation.hpp"
#include "common/vec3.hpp"

namespace openmss::mechanics {

// Euler parameters of rotation matrix r (e0 >= 0), component 0..3.
template <class T>
T eulerParameterOf(const M3<T>& r, int component) {
  const double a00 = valueOf(r.at(0, 0)), a11 = valueOf(r.at(1, 1)), a22 = valueOf(r.at(2, 2));
  const double tr = a00 + a11 + a22;
  T q[4];
  if (tr >= a00 && tr >= a11 && tr >= a22) {
    const T s = sqrtOf(1.0 + r.at(0, 0) + r.at(1, 1) + r.at(2, 2)) * 2.0;
    q[0] = 0.25 * s;
    q[1] = (r.at(2, 1) - r.at(1, 2)) / s;
    q[2] = (r.at(0, 2) - r.at(2, 0)) / s;
    q[3] = (r.at(1, 0) - r.at(0, 1)) / s;
  } else if (a00 >= a11 && a00 >= a22) {
    const T s = sqrtOf(1.0 + r.at(0, 0) - r.at(1, 1) - r.at(2, 2)) * 2.0;
    q[0] = (r.at(2, 1) - r.at(1, 2)) / s;
    q[1] = 0.25 * s;
    q[2] = (r.at(0, 1) + r.at(1, 0)) / s;
    q[3] = (r.at(0, 2) + r.at(2, 0)) / s;
  } else if (a11 >= a22) {
    const T s = sqrtOf(1.0 - r.at(0, 0) + r.at(1, 1) - r.at(2, 2)) * 2.0;
    q[0] = (r.at(0, 2) - r.at(2, 0)) / s;
    q[1] = (r.at(0, 1) + r.at(1, 0)) / s;
    q[2] = 0.25 * s;
    q[3] = (r.at(1, 2) + r.at(2, 1)) / s;
  } else {
    const T s = sqrtOf(1.0 - r.at(0, 0) - r.at(1, 1) + r.at(2, 2)) * 2.0;
    q[0] = (r.at(1, 0) - r.at(0, 1)) / s;
    q[1] = (r.at(0, 2) + r.at(2, 0)) / s;
    q[2] = (r.at(1, 2) + r.at(2, 1)) / s;
    q[3] = 0.25 * s;
  }
  const T length = sqrtOf(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double sign = valueOf(q[0]) < 0.0 ? -1.0 : 1.0;  // q and -q are one orientation
  return sign * q[component] / length;
}

// Body-fixed angle `component` (0..2) of the sequence i-j-k (0 = x, 1 = y, 2 = z) of r.
template <class T>
T bodyFixedAngleOf(const M3<T>& r, int i, int j, int k, int component) {
  if (i == k) {
    // Proper Euler sequence i-j-i; o the third axis, eps the parity of (i, j, o).
    const int o = 3 - i - j;
    const double eps = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
    const double rii = valueOf(r.at(i, i));
    const double sine = std::sqrt(valueOf(r.at(j, i)) * valueOf(r.at(j, i)) +
                                  valueOf(r.at(o, i)) * valueOf(r.at(o, i)));
    if (component == 1) return acosOf(r.at(i, i));
    if (sine < 1e-12) {  // gimbal lock: the first angle takes the whole turn
      if (component == 2) return T(0.0);
      return atan2Of(-eps * (rii > 0 ? 1.0 : -1.0) * r.at(j, o), r.at(j, j));
    }
    if (component == 0) return atan2Of(r.at(j, i), -eps * r.at(o, i));
    return atan2Of(r.at(i, j), eps * r.at(i, o));
  }
  // Tait-Bryan sequence i-j-k; eps the parity of (i, j, k).
  const double eps = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const T s2 = eps * r.at(i, k);
  if (component == 1) {
    // asin(s2) written as atan2 so that the dual arithmetic needs no arcsine.
    const T c2 = sqrtOf(r.at(i, i) * r.at(i, i) + r.at(i, j) * r.at(i, j));
    return atan2Of(s2, c2);
  }
  if (std::abs(valueOf(s2)) > 1.0 - 1e-12) {
    if (component == 2) return T(0.0);
    return atan2Of(eps * r.at(k, j), r.at(j, j));
  }
  if (component == 0) return atan2Of(-eps * r.at(j, k), r.at(k, k));
  return atan2Of(-eps * r.at(i, j), r.at(i, i));
}

// ORIENT(code, component, ...) of I relative to J, r = A_J^T A_I. False for codes not handled.
template <class T>
bool orientValue(const M3<T>& r, int code, int component, T* out) {
  if (code == 27) {
    *out = eulerParameterOf(r, component - 1);
    return true;
  }
  // Code 28 (funcs): Rodriguez parameters e_k / e0, components 1-3, as RCNVRT defines them
  // (infinite at a half turn, where e0 = 0). Code 29: direction cosine n (1-9) of r, numbered
  // down the columns as RCNVRT's COSINES array, so 1-3 are the x axis of I resolved in J.
  // UVX/UVY/UVZ and TRANS expand into code 29 (docs/expressions.md, "ORIENT codes").
  if (code == 28) {
    *out = eulerParameterOf(r, component) / eulerParameterOf(r, 0);
    return true;
  }
  if (code == 29) {
    *out = r.at((component - 1) % 3, (component - 1) / 3);
    return true;
  }
  // Codes 25 and 26 (expr4): AX, AY, AZ as principal angles and YAW, PITCH, ROLL (PITCH the
  // negated second 3-2-1 angle), as those functions define them (docs/expressions.md).
  if (code == 25) {
    if (component == 1) *out = atan2Of(-r.at(1, 2), r.at(2, 2));
    else if (component == 2) *out = atan2Of(r.at(0, 2), r.at(2, 2));
    else *out = atan2Of(r.at(1, 0), r.at(0, 0));
    return true;
  }
  if (code == 26) {
    *out = (component == 2 ? -1.0 : 1.0) * bodyFixedAngleOf(r, 2, 1, 0, component - 1);
    return true;
  }
  int a = 0, b = 0, c = 0, k = 0;  // codes 1-24: body- and space-fixed sequences (expr4)
  if (!orientBodySequence(code, component, &a, &b, &c, &k)) return false;
  *out = bodyFixedAngleOf(r, a, b, c, k - 1);
  return true;
}

}  // namespace openmss::mechanics
