#include "common/rotation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace openmss {

namespace {

// sin and cos that are exact at multiples of 90 degrees: data sets write 90D, 180D, and
// cos(pi/2) = 6e-17 would tilt a frame that the user meant to be exactly square, seeding
// out-of-plane motion in planar mechanisms.
void exactSinCos(double a, double* s, double* c) {
  const double quarter = std::round(a / (0.5 * std::numbers::pi));
  if (std::abs(a - quarter * 0.5 * std::numbers::pi) <= 1e-14 * std::max(1.0, std::abs(a))) {
    static const double sv[4] = {0.0, 1.0, 0.0, -1.0};
    static const double cv[4] = {1.0, 0.0, -1.0, 0.0};
    const int q = static_cast<int>(((static_cast<long long>(quarter) % 4) + 4) % 4);
    *s = sv[q];
    *c = cv[q];
    return;
  }
  *s = std::sin(a);
  *c = std::cos(a);
}

}  // namespace

Eigen::Matrix3d matrixFromEuler313(double psi, double theta, double phi) {
  double cps, sps, cth, sth, cph, sph;
  exactSinCos(psi, &sps, &cps);
  exactSinCos(theta, &sth, &cth);
  exactSinCos(phi, &sph, &cph);
  Eigen::Matrix3d a;
  a << cps * cph - sps * cth * sph, -cps * sph - sps * cth * cph, sps * sth,
      sps * cph + cps * cth * sph, -sps * sph + cps * cth * cph, -cps * sth,
      sth * sph, sth * cph, cth;
  return a;
}

Eigen::Vector3d euler313FromMatrix(const Eigen::Matrix3d& a) {
  const double c = std::clamp(a(2, 2), -1.0, 1.0);
  const double theta = std::acos(c);
  const double s = std::sqrt(a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2));
  if (s < 1e-12) {
    // Gimbal lock: only psi + phi (theta = 0) or psi - phi (theta = pi) is defined.
    return {std::atan2(a(1, 0), a(0, 0)), theta, 0.0};
  }
  return {std::atan2(a(0, 2), -a(1, 2)), theta, std::atan2(a(2, 0), a(2, 1))};
}

namespace {

// The default toward-point direction of an axis-point frame whose point is missing: the
// reference axis `preferred`, or y when the exact axis lies along it (documented choice).
Eigen::Vector3d defaultPlaneAxis(const Eigen::Vector3d& exact, const Eigen::Vector3d& preferred) {
  return std::abs(exact.dot(preferred)) > 0.999 ? Eigen::Vector3d::UnitY() : preferred;
}

// `plane` made orthogonal to the unit `exact` axis and normalised; false when it lies along it.
bool orthogonalise(const Eigen::Vector3d& exact, Eigen::Vector3d& plane) {
  plane -= exact * exact.dot(plane);
  if (plane.norm() < 1e-12) return false;
  plane.normalize();
  return true;
}

void setAxes(const Eigen::Vector3d& x, const Eigen::Vector3d& z, Eigen::Matrix3d* a) {
  a->col(0) = x;
  a->col(1) = z.cross(x);
  a->col(2) = z;
}

}  // namespace

bool matrixFromAxisPoints(const Eigen::Vector3d& origin, const Eigen::Vector3d& zPoint,
                          const Eigen::Vector3d& xPoint, bool zGiven, bool xGiven,
                          Eigen::Matrix3d* a) {
  Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  if (zGiven) {
    z = zPoint - origin;
    if (z.norm() < 1e-12) return false;
    z.normalize();
  }
  Eigen::Vector3d x =
      xGiven ? Eigen::Vector3d(xPoint - origin) : defaultPlaneAxis(z, Eigen::Vector3d::UnitX());
  if (!orthogonalise(z, x)) return false;
  setAxes(x, z, a);
  return true;
}

bool matrixFromAxisPointsUseX(const Eigen::Vector3d& origin, const Eigen::Vector3d& zPoint,
                              const Eigen::Vector3d& xPoint, bool zGiven, Eigen::Matrix3d* a) {
  Eigen::Vector3d x = xPoint - origin;
  if (x.norm() < 1e-12) return false;
  x.normalize();
  Eigen::Vector3d z =
      zGiven ? Eigen::Vector3d(zPoint - origin) : defaultPlaneAxis(x, Eigen::Vector3d::UnitZ());
  if (!orthogonalise(x, z)) return false;
  setAxes(x, z, a);
  return true;
}

Eigen::Vector3d bodyFixedAngles(const Eigen::Matrix3d& r, int i, int j, int k) {
  if (i == k) {
    // Proper Euler sequence i-j-i; `o` is the third axis, eps the parity of (i, j, o).
    const int o = 3 - i - j;
    const double eps = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
    const double t2 = std::acos(std::clamp(r(i, i), -1.0, 1.0));
    if (std::sqrt(r(j, i) * r(j, i) + r(o, i) * r(o, i)) < 1e-12)
      return {std::atan2(-eps * r(j, o) * (r(i, i) > 0 ? 1.0 : -1.0), r(j, j)), t2, 0.0};
    return {std::atan2(r(j, i), -eps * r(o, i)), t2, std::atan2(r(i, j), eps * r(i, o))};
  }
  // Tait-Bryan sequence i-j-k; eps the parity of (i, j, k).
  const double eps = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const double s2 = std::clamp(eps * r(i, k), -1.0, 1.0);
  const double t2 = std::asin(s2);
  if (std::abs(s2) > 1.0 - 1e-12)
    return {std::atan2(eps * r(k, j), r(j, j)), t2, 0.0};
  return {std::atan2(-eps * r(j, k), r(k, k)), t2, std::atan2(-eps * r(i, j), r(i, i))};
}

bool orientSequence(int code, int* first, int* second, int* third) {
  static const int table[10][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2},
                                   {2, 1, 0}, {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1}};
  if (code < 1 || code > 10) return false;
  *first = table[code - 1][0];
  *second = table[code - 1][1];
  *third = table[code - 1][2];
  return true;
}

bool orientBodySequence(int code, int component, int* first, int* second, int* third,
                        int* bodyComponent) {
  static const int table[12][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1},
                                   {1, 0, 2}, {2, 1, 0}, {0, 1, 0}, {0, 2, 0},
                                   {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}};
  if (code < 1 || code > 24 || component < 1 || component > 3) return false;
  const int* axes = table[(code - 1) % 12];
  const bool spaceFixed = code > 12;
  *first = spaceFixed ? axes[2] : axes[0];
  *second = axes[1];
  *third = spaceFixed ? axes[0] : axes[2];
  *bodyComponent = spaceFixed ? 4 - component : component;
  return true;
}

Eigen::Vector4d quaternionFromMatrix(const Eigen::Matrix3d& a) {
  const double tr = a.trace();
  Eigen::Vector4d q;
  if (tr >= a(0, 0) && tr >= a(1, 1) && tr >= a(2, 2)) {
    const double s = std::sqrt(1.0 + tr) * 2.0;
    q << 0.25 * s, (a(2, 1) - a(1, 2)) / s, (a(0, 2) - a(2, 0)) / s, (a(1, 0) - a(0, 1)) / s;
  } else if (a(0, 0) >= a(1, 1) && a(0, 0) >= a(2, 2)) {
    const double s = std::sqrt(1.0 + a(0, 0) - a(1, 1) - a(2, 2)) * 2.0;
    q << (a(2, 1) - a(1, 2)) / s, 0.25 * s, (a(0, 1) + a(1, 0)) / s, (a(0, 2) + a(2, 0)) / s;
  } else if (a(1, 1) >= a(2, 2)) {
    const double s = std::sqrt(1.0 - a(0, 0) + a(1, 1) - a(2, 2)) * 2.0;
    q << (a(0, 2) - a(2, 0)) / s, (a(0, 1) + a(1, 0)) / s, 0.25 * s, (a(1, 2) + a(2, 1)) / s;
  } else {
    const double s = std::sqrt(1.0 - a(0, 0) - a(1, 1) + a(2, 2)) * 2.0;
    q << (a(1, 0) - a(0, 1)) / s, (a(0, 2) + a(2, 0)) / s, (a(1, 2) + a(2, 1)) / s, 0.25 * s;
  }
  if (q(0) < 0) q = -q;
  return q.normalized();
}

}  // namespace openmss
